#include "lua/host/field_hint.h"

#include <cstring>
#include <lua.hpp>

#include "core/strings.h"

namespace essaim {

namespace {
// The field a Lua error message names: "(field 'x')" or "(method 'x')"; "" when none.
std::string NamedField(const char* message) {
  for (const char* marker : {"(field '", "(method '"}) {
    const char* start = std::strstr(message, marker);
    if (!start) continue;
    start += std::strlen(marker);
    const char* end = std::strchr(start, '\'');
    if (end) return std::string(start, end);
  }
  return "";
}

// The string keys of the table at the top of the stack, each as `prefix.key`, and (one level
// down) those of its table values. Raw reads only: no metamethod runs inside the handler.
void CollectKeys(lua_State* L, const std::string& prefix, int depth, std::vector<std::string>* paths) {
  lua_pushnil(L);
  while (lua_next(L, -2)) {
    if (lua_type(L, -2) == LUA_TSTRING) {
      const std::string path = prefix + "." + lua_tostring(L, -2);
      paths->push_back(path);
      if (depth > 0 && lua_type(L, -1) == LUA_TTABLE) CollectKeys(L, path, depth - 1, paths);
    }
    lua_pop(L, 1);
  }
}

std::string LastPart(const std::string& path) { return path.substr(path.rfind('.') + 1); }
}  // namespace

std::string FieldHint(lua_State* L, const char* message, const char* root, const std::vector<AbsentField>& absent) {
  const std::string field = message ? NamedField(message) : "";
  if (field.empty() || !lua_checkstack(L, 8)) return "";
  std::vector<std::string> paths;
  lua_rawgeti(L, LUA_REGISTRYINDEX, LUA_RIDX_GLOBALS);
  lua_pushstring(L, root);
  if (lua_rawget(L, -2) == LUA_TTABLE) CollectKeys(L, root, 1, &paths);
  lua_pop(L, 2);
  std::vector<std::string> names;
  for (const std::string& p : paths) {
    if (LastPart(p) == field) return "";  // the name exists: the nil came from somewhere else
    names.push_back(LastPart(p));
  }
  for (const AbsentField& a : absent)
    if (a.name == field) return "; " + a.why;
  const std::string best = ClosestName(field, names);
  if (best.empty()) return "";
  for (const std::string& p : paths)
    if (LastPart(p) == best) return "; did you mean " + p + "?";
  return "";
}

}  // namespace essaim
