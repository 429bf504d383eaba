#include "lua/host/log_text.h"

#include <cstdio>
#include <lua.hpp>

namespace essaim {

void AppendArgosLogText(lua_State* L, std::string* out) {
  const int n = lua_gettop(L);
  for (int i = 1; i <= n; ++i) {
    switch (lua_type(L, i)) {
      case LUA_TNUMBER: {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", lua_tonumber(L, i));  // std::ostream's default
        *out += buf;
        break;
      }
      case LUA_TSTRING: {
        size_t len = 0;
        const char* s = lua_tolstring(L, i, &len);
        out->append(s, len);
        break;
      }
      case LUA_TBOOLEAN:
        *out += lua_toboolean(L, i) ? '1' : '0';
        break;
      default:
        *out += luaL_typename(L, i);
    }
  }
}

void EndLogEntry(std::string* log, size_t begin) {
  const char stream = (*log)[begin];
  for (size_t i = log->find('\n', begin); i != std::string::npos; i = log->find('\n', i + 2))
    log->insert(i + 1, 1, stream);
  *log += '\n';
}

}  // namespace essaim
