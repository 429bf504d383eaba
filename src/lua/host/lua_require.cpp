#include "lua/host/lua_require.h"

#include <exception>
#include <lua.hpp>

#include "core/input_files.h"
#include "lua/host/guard_hook.h"

namespace essaim {

namespace {
// Upvalues: the searcher it wraps, the InputFiles. A searcher that found the module returns
// its loader and the file name; anything else passes through as it came.
int RecordingSearcher(lua_State* L) {
  auto* inputs = static_cast<InputFiles*>(lua_touserdata(L, lua_upvalueindex(2)));
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, lua_gettop(L) - 1, LUA_MULTRET);
  const int n = lua_gettop(L);
  if (n >= 2 && lua_isfunction(L, 1) && lua_type(L, 2) == LUA_TSTRING) {
    bool added = true;
    try {  // no C++ exception may cross Lua's C frames
      inputs->Add(lua_tostring(L, 2), "module");
    } catch (const std::exception&) {
      added = false;
    }
    if (!added) return luaL_error(L, "out of memory recording module '%s'", lua_tostring(L, 2));
  }
  return n;
}
}  // namespace

void RecordRequiredFiles(lua_State* L, InputFiles* inputs) {
  if (!inputs) return;
  lua_getglobal(L, "package");
  if (IsUnopenedLibrary(L, -1))
    GuardOf(L)->module_inputs = inputs;
  else if (lua_istable(L, -1))
    WrapModuleSearcher(L, lua_gettop(L), inputs);
  lua_pop(L, 1);
}

void WrapModuleSearcher(lua_State* L, int package, InputFiles* inputs) {
  const int top = lua_gettop(L);
  if (lua_getfield(L, package, "searchers") == LUA_TTABLE && lua_rawgeti(L, -1, 2) == LUA_TFUNCTION) {
    lua_pushlightuserdata(L, inputs);
    lua_pushcclosure(L, RecordingSearcher, 2);
    lua_rawseti(L, -2, 2);
  }
  lua_settop(L, top);
}

}  // namespace essaim
