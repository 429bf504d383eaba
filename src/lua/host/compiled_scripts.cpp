#include "lua/host/compiled_scripts.h"

#include <exception>
#include <lua.hpp>

namespace essaim {

namespace {
// lua_dump's writer: no C++ exception may cross Lua's C frames; a failure only means the
// chunk is not kept (the next state parses the file itself).
int AppendBytes(lua_State*, const void* bytes, size_t size, void* out) {
  try {
    static_cast<std::string*>(out)->append(static_cast<const char*>(bytes), size);
  } catch (const std::exception&) {
    return 1;
  }
  return 0;
}
}  // namespace

int CompiledScripts::Load(lua_State* L, const std::string& path, bool text_only) {
  const std::string key = (text_only ? "t:" : "bt:") + path;
  auto found = bytecode_.find(key);
  if (found != bytecode_.end()) {
    // Our own dump: binary mode for this buffer only; "@path" as luaL_loadfile names it.
    const std::string chunkname = "@" + path;
    return luaL_loadbufferx(L, found->second.data(), found->second.size(), chunkname.c_str(), "b");
  }
  const int status = luaL_loadfilex(L, path.c_str(), text_only ? "t" : nullptr);
  if (status != LUA_OK) return status;
  std::string bytecode;
  if (lua_dump(L, AppendBytes, &bytecode, /*strip=*/0) == 0) bytecode_.emplace(key, std::move(bytecode));
  return status;
}

}  // namespace essaim
