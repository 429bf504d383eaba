#include "lua/robot/lua_params.h"

#include <algorithm>
#include <lua.hpp>

namespace essaim {

namespace {
// Upvalue 1: the values; upvalue 2: the set of keys read (key -> true).
void MarkRead(lua_State* L, int key) {
  if (lua_type(L, key) != LUA_TSTRING) return;
  key = lua_absindex(L, key);
  lua_pushvalue(L, key);
  if (lua_rawget(L, lua_upvalueindex(2)) == LUA_TNIL) {  // allocates only the first time
    lua_pushvalue(L, key);
    lua_pushboolean(L, 1);
    lua_rawset(L, lua_upvalueindex(2));
  }
  lua_pop(L, 1);
}

int Index(lua_State* L) {  // (proxy, key)
  MarkRead(L, 2);
  lua_pushvalue(L, 2);
  lua_rawget(L, lua_upvalueindex(1));
  return 1;
}

int NewIndex(lua_State* L) {  // (proxy, key, value)
  lua_settop(L, 3);
  lua_rawset(L, lua_upvalueindex(1));
  return 0;
}

int Next(lua_State* L) {  // (state, key): lua_next over the values, marking each key
  lua_settop(L, 2);
  if (!lua_next(L, lua_upvalueindex(1))) return 0;
  MarkRead(L, -2);
  return 2;
}

int Pairs(lua_State* L) {
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_pushvalue(L, lua_upvalueindex(2));
  lua_pushcclosure(L, Next, 2);
  lua_pushnil(L);
  lua_pushnil(L);
  return 3;
}

int Len(lua_State* L) {
  lua_pushinteger(L, static_cast<lua_Integer>(lua_rawlen(L, lua_upvalueindex(1))));
  return 1;
}
}  // namespace

void PushTrackedParams(lua_State* L, TrackedParams* refs) {
  const int values = lua_gettop(L);
  lua_newtable(L);  // keys read
  const int read = values + 1;
  lua_pushvalue(L, values);
  refs->values_ref = luaL_ref(L, LUA_REGISTRYINDEX);
  lua_pushvalue(L, read);
  refs->read_ref = luaL_ref(L, LUA_REGISTRYINDEX);
  lua_newtable(L);  // the proxy
  lua_createtable(L, 0, 4);
  const std::pair<const char*, lua_CFunction> methods[] = {
      {"__index", Index}, {"__newindex", NewIndex}, {"__pairs", Pairs}, {"__len", Len}};
  for (auto [name, fn] : methods) {
    lua_pushvalue(L, values);
    lua_pushvalue(L, read);
    lua_pushcclosure(L, fn, 2);
    lua_setfield(L, -2, name);
  }
  lua_setmetatable(L, -2);
  lua_replace(L, values);
  lua_settop(L, values);
}

void ListParamReads(lua_State* L, const TrackedParams& refs, std::vector<std::string>* unread,
                    std::vector<std::string>* read) {
  if (!L || refs.values_ref < 0) return;
  lua_rawgeti(L, LUA_REGISTRYINDEX, refs.read_ref);
  const int seen = lua_gettop(L);
  for (lua_pushnil(L); lua_next(L, seen); lua_pop(L, 1))
    if (lua_type(L, -2) == LUA_TSTRING) read->push_back(lua_tostring(L, -2));
  lua_rawgeti(L, LUA_REGISTRYINDEX, refs.values_ref);
  const int values = lua_gettop(L);
  for (lua_pushnil(L); lua_next(L, values); lua_pop(L, 1)) {
    if (lua_type(L, -2) != LUA_TSTRING || lua_type(L, -1) != LUA_TSTRING) continue;
    lua_pushvalue(L, -2);
    const bool was_read = lua_rawget(L, seen) != LUA_TNIL;
    lua_pop(L, 1);
    if (!was_read) unread->push_back(lua_tostring(L, -2));
  }
  lua_settop(L, seen - 1);
  std::sort(unread->begin(), unread->end());
  std::sort(read->begin(), read->end());
}

}  // namespace essaim
