// The standard libraries few controllers use, opened at their first use. Opening every
// library cost a state ~8 µs and ~6 KB (of ~100 µs and ~35 KB for a simple controller at
// 100 000 robots); most controllers never touch coroutine, io, os, utf8 or debug.
//
// Each global is its library's final table from the start, so that a kept reference
// (`local io = io`, package.loaded.io, require "io") is the same table before and after.
// Until first used it is empty, with a metatable whose __index, __newindex and __pairs
// fill it (the library's fields, guarded), drop the metatable and carry on. What a script
// can tell apart before that: next(), rawget() and rawlen() see an empty table and
// getmetatable() returns the loader's.
#include <lua.hpp>

#include "lua/host/guard_hook.h"

namespace essaim {

namespace {
struct LazyLibrary {
  const char* name;
  lua_CFunction open;
  bool sandboxed;  // kept under the sandbox
};
constexpr LazyLibrary kLazyLibraries[] = {{"coroutine", luaopen_coroutine, true},
                                          {"utf8", luaopen_utf8, true},
                                          {"io", luaopen_io, false},
                                          {"os", luaopen_os, false},
                                          {"debug", luaopen_debug, false}};
// The metatable's array part: the library's index in kLazyLibraries, and base's next and
// error as they were when the state was made (a script may replace the globals since).
constexpr int kLibraryIndex = 1, kNext = 2, kError = 3;

// Opens the library of the placeholder at stack index `t` into it: its fields are added
// where the placeholder has none (a raw set before first use stays), and the metatable
// goes first, so nothing here calls back into the loader.
void Fill(lua_State* L, int t) {
  lua_getmetatable(L, t);
  lua_rawgeti(L, -1, kLibraryIndex);
  const LazyLibrary& lib = kLazyLibraries[lua_tointeger(L, -1)];
  lua_rawgeti(L, -2, kError);
  const int base_error = lua_gettop(L);
  lua_pushnil(L);
  lua_setmetatable(L, t);
  lua_pushcfunction(L, lib.open);
  lua_call(L, 0, 1);
  GuardLibrary(L, lib.name, base_error);
  lua_pushnil(L);
  while (lua_next(L, -2)) {  // library, key, value
    lua_pushvalue(L, -2);
    if (lua_rawget(L, t) != LUA_TNIL) {
      lua_pop(L, 2);
      continue;
    }
    lua_pop(L, 1);
    lua_pushvalue(L, -2);
    lua_insert(L, -2);
    lua_rawset(L, t);
  }
  lua_pop(L, 4);  // the library, error, the index, the metatable
}

int FillThenIndex(lua_State* L) {  // (t, key)
  Fill(L, 1);
  lua_settop(L, 2);
  lua_rawget(L, 1);
  return 1;
}
int FillThenNewIndex(lua_State* L) {  // (t, key, value)
  Fill(L, 1);
  lua_settop(L, 3);
  lua_rawset(L, 1);
  return 0;
}
int FillThenPairs(lua_State* L) {  // (t): next, t, nil as pairs() gives them
  lua_getmetatable(L, 1);
  lua_rawgeti(L, -1, kNext);
  lua_replace(L, -2);
  Fill(L, 1);
  lua_pushvalue(L, 1);
  lua_pushnil(L);
  return 3;
}
}  // namespace

void DeclareLazyLibraries(lua_State* L, bool sandbox) {
  lua_getfield(L, LUA_REGISTRYINDEX, LUA_LOADED_TABLE);
  const int loaded = lua_gettop(L);
  lua_getglobal(L, "next");
  const int next = lua_gettop(L);
  lua_getglobal(L, "error");
  const int error = lua_gettop(L);
  int index = 0;
  for (const LazyLibrary& lib : kLazyLibraries) {
    const int i = index++;
    if (sandbox && !lib.sandboxed) continue;
    lua_createtable(L, 0, 0);
    lua_createtable(L, 3, 3);
    lua_pushinteger(L, i);
    lua_rawseti(L, -2, kLibraryIndex);
    lua_pushvalue(L, next);
    lua_rawseti(L, -2, kNext);
    lua_pushvalue(L, error);
    lua_rawseti(L, -2, kError);
    lua_pushcfunction(L, FillThenIndex);  // light C functions: nothing allocated
    lua_setfield(L, -2, "__index");
    lua_pushcfunction(L, FillThenNewIndex);
    lua_setfield(L, -2, "__newindex");
    lua_pushcfunction(L, FillThenPairs);
    lua_setfield(L, -2, "__pairs");
    lua_setmetatable(L, -2);
    lua_pushvalue(L, -1);
    lua_setfield(L, loaded, lib.name);
    lua_setglobal(L, lib.name);
  }
  lua_settop(L, loaded - 1);
}

}  // namespace essaim
