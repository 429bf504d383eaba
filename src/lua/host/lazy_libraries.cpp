// The standard libraries a controller may never use, opened at their first use. Opening every
// library cost a state ~8 µs and ~6 KB (of ~100 µs and ~35 KB for a simple controller at
// 100 000 robots); most controllers never touch coroutine, io, os, utf8 or debug, and many
// not table, string or package. A state's collector lets garbage grow in proportion to
// what it keeps, so each KB not kept saves ~1.5 KB of its peak.
//
// Each global is its library's final table from the start, so that a kept reference
// (`local io = io`, package.loaded.io, require "io") is the same table before and after.
// Until first used it is empty, with a metatable whose __index, __newindex and __pairs
// fill it (the library's fields, guarded), drop the metatable and carry on. What a script
// can tell apart before that: next(), rawget() and rawlen() see an empty table and
// getmetatable() returns the loader's.
//
// `require` opens package at its first call. luaopen_package's require and searchers look
// up package's fields through an upvalue: they are pointed at the placeholder, so that
// package.path set by a script is the one they read.
//
// Strings need their metatable from the start: Lua 5.4's string-to-number arithmetic
// ("10" + 1) is the string library's metamethods. It has them (Lua's own functions) and
// an __index that is the `string` placeholder, so ("x"):upper() opens the library.
#include <lua.hpp>
#include <string>
#include <utility>
#include <vector>

#include "lua/host/guard_hook.h"

namespace essaim {

namespace {
// One metatable serves every placeholder of a state: its array part holds base's next and
// error as they were when the state was made (a script may replace the globals since), its
// hash part each placeholder's index in kLazyLibraries.
constexpr int kNext = 1, kError = 2;
// The registry's key of luaopen_package's require, which the placeholder require calls.
const char kRealRequire = 0;

int FillThenIndex(lua_State* L);
void Fill(lua_State* L, int t);

using NamedFunctions = std::vector<std::pair<std::string, lua_CFunction>>;

// The string library's metamethods (__add, __index...), read once from a scratch state:
// C functions, so every state can share them without allocating.
const NamedFunctions& StringMetamethods() {
  static const NamedFunctions kFunctions = [] {
    NamedFunctions out;
    lua_State* L = luaL_newstate();
    if (!L) return out;
    luaL_requiref(L, LUA_STRLIBNAME, luaopen_string, 0);
    lua_pushliteral(L, "");
    lua_getmetatable(L, -1);
    lua_pushnil(L);
    while (lua_next(L, -2)) {
      if (lua_type(L, -2) == LUA_TSTRING && lua_iscfunction(L, -1))
        out.emplace_back(lua_tostring(L, -2), lua_tocfunction(L, -1));
      lua_pop(L, 1);
    }
    lua_close(L);
    return out;
  }();
  return kFunctions;
}

// Strings' metatable: the library's metamethods, __index the placeholder on top.
void SetStringMetatable(lua_State* L) {
  const NamedFunctions& functions = StringMetamethods();
  lua_createtable(L, 0, static_cast<int>(functions.size()) + 1);
  for (const auto& [name, fn] : functions) {
    lua_pushcfunction(L, fn);
    lua_setfield(L, -2, name.c_str());
  }
  lua_pushvalue(L, -2);
  lua_setfield(L, -2, "__index");
  lua_pushliteral(L, "");
  lua_insert(L, -2);
  lua_setmetatable(L, -2);
  lua_pop(L, 1);
}

// require before package is opened (upvalue: package's placeholder): opens it, then calls
// luaopen_package's require.
int LazyRequire(lua_State* L) {
  const int args = lua_gettop(L);
  lua_pushvalue(L, lua_upvalueindex(1));
  if (IsUnopenedLibrary(L, args + 1)) Fill(L, args + 1);
  lua_settop(L, args);
  lua_rawgetp(L, LUA_REGISTRYINDEX, &kRealRequire);
  lua_insert(L, 1);
  lua_call(L, args, LUA_MULTRET);
  return lua_gettop(L);
}

// The C closure at the top: if its first upvalue is the table at `fresh`, it becomes `t`.
void Retarget(lua_State* L, int fresh, int t) {
  if (!lua_getupvalue(L, -1, 1)) return;
  const bool same = lua_rawequal(L, -1, fresh);
  lua_pop(L, 1);
  if (!same) return;
  lua_pushvalue(L, t);
  lua_setupvalue(L, -2, 1);
}

// With luaopen_package's table on top and the global require before it under it: require
// and the searchers read the placeholder `t`, require is kept in the registry, and the
// global is put back unless it still was the placeholder's require.
void AdoptPackage(lua_State* L, int t) {
  const int fresh = lua_gettop(L), before = fresh - 1;
  lua_getglobal(L, "require");
  Retarget(L, fresh, t);
  lua_rawsetp(L, LUA_REGISTRYINDEX, &kRealRequire);
  if (lua_getfield(L, fresh, "searchers") == LUA_TTABLE) {
    for (lua_Integer i = 1; lua_rawgeti(L, -1, i) != LUA_TNIL; ++i) {
      Retarget(L, fresh, t);
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  if (lua_tocfunction(L, before) != LazyRequire) {
    lua_pushvalue(L, before);
    lua_setglobal(L, "require");
  }
  lua_remove(L, before);
}

// luaopen_string into a fresh table, left on top. It gives strings a metatable of its own:
// the one they had (whose __index is the placeholder) is put back.
void OpenStrings(lua_State* L, lua_CFunction open, int) {
  lua_pushliteral(L, "");
  lua_getmetatable(L, -1);
  lua_remove(L, -2);
  lua_pushcfunction(L, open);
  lua_call(L, 0, 1);
  lua_pushliteral(L, "");
  lua_pushvalue(L, -3);
  lua_setmetatable(L, -2);
  lua_pop(L, 1);
  lua_remove(L, -2);
}

// luaopen_package into a fresh table, left on top, adopted by the placeholder `t`.
void OpenPackage(lua_State* L, lua_CFunction open, int t) {
  lua_getglobal(L, "require");
  lua_pushcfunction(L, open);
  lua_call(L, 0, 1);
  AdoptPackage(L, t);
}

// With package's placeholder on top: the global require that opens it.
void DeclareRequire(lua_State* L) {
  lua_pushvalue(L, -1);
  lua_pushcclosure(L, LazyRequire, 1);
  lua_setglobal(L, "require");
}

struct LazyLibrary {
  const char* name;
  lua_CFunction open;
  bool sandboxed;  // kept under the sandbox
  // Called with the placeholder on top once it is declared; null: nothing more.
  void (*declared)(lua_State* L) = nullptr;
  // Opens the library for the placeholder at `t`, its fresh table left on top; null: `open`
  // called as it is.
  void (*opener)(lua_State* L, lua_CFunction open, int t) = nullptr;
};
constexpr LazyLibrary kLazyLibraries[] = {{"table", luaopen_table, true},
                                          {"string", luaopen_string, true, SetStringMetatable, OpenStrings},
                                          {"package", luaopen_package, true, DeclareRequire, OpenPackage},
                                          {"coroutine", luaopen_coroutine, true},
                                          {"utf8", luaopen_utf8, true},
                                          {"io", luaopen_io, false},
                                          {"os", luaopen_os, false},
                                          {"debug", luaopen_debug, false}};

// Opens the library of the placeholder at stack index `t` into it: its fields are added
// where the placeholder has none (a raw set before first use stays), and the metatable
// goes first, so nothing here calls back into the loader.
void Fill(lua_State* L, int t) {
  lua_getmetatable(L, t);
  lua_pushvalue(L, t);
  lua_rawget(L, -2);
  const LazyLibrary& lib = kLazyLibraries[lua_tointeger(L, -1)];
  lua_rawgeti(L, -2, kError);
  const int base_error = lua_gettop(L);
  lua_pushnil(L);
  lua_setmetatable(L, t);
  if (lib.opener) {
    lib.opener(L, lib.open, t);
  } else {
    lua_pushcfunction(L, lib.open);
    lua_call(L, 0, 1);
  }
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

// The placeholders' shared metatable, left on top.
void PushLoaderMetatable(lua_State* L) {
  lua_createtable(L, 2, 3 + static_cast<int>(std::size(kLazyLibraries)));
  lua_getglobal(L, "next");
  lua_rawseti(L, -2, kNext);
  lua_getglobal(L, "error");
  lua_rawseti(L, -2, kError);
  lua_pushcfunction(L, FillThenIndex);  // light C functions: nothing allocated
  lua_setfield(L, -2, "__index");
  lua_pushcfunction(L, FillThenNewIndex);
  lua_setfield(L, -2, "__newindex");
  lua_pushcfunction(L, FillThenPairs);
  lua_setfield(L, -2, "__pairs");
}
}  // namespace

bool IsUnopenedLibrary(lua_State* L, int index) {
  if (!lua_getmetatable(L, index)) return false;
  lua_pushliteral(L, "__index");
  lua_rawget(L, -2);
  const bool unopened = lua_tocfunction(L, -1) == FillThenIndex;
  lua_pop(L, 2);
  return unopened;
}

void DeclareLazyLibraries(lua_State* L, bool sandbox) {
  lua_getfield(L, LUA_REGISTRYINDEX, LUA_LOADED_TABLE);
  const int loaded = lua_gettop(L);
  PushLoaderMetatable(L);
  const int metatable = lua_gettop(L);
  lua_Integer index = 0;
  for (const LazyLibrary& lib : kLazyLibraries) {
    const lua_Integer i = index++;
    if (sandbox && !lib.sandboxed) continue;
    lua_createtable(L, 0, 0);
    lua_pushvalue(L, -1);
    lua_pushinteger(L, i);
    lua_rawset(L, metatable);
    lua_pushvalue(L, metatable);
    lua_setmetatable(L, -2);
    if (lib.declared) lib.declared(L);
    lua_pushvalue(L, -1);
    lua_setfield(L, loaded, lib.name);
    lua_setglobal(L, lib.name);
  }
  lua_settop(L, loaded - 1);
}

}  // namespace essaim
