#include "lua/loop/lua_to_value.h"

#include <algorithm>
#include <cmath>
#include <lua.hpp>

#include "core/strings.h"

namespace essaim {

namespace {

std::string LuaString(lua_State* L, int idx) {
  size_t len = 0;
  const char* p = lua_tolstring(L, idx, &len);
  return std::string(p, len);  // whole, NUL bytes included
}

struct ValueWalk {
  lua_State* L;
  std::vector<std::string>* nonfinite;
  std::string* error;

  bool Fail(std::string message) {
    *error = std::move(message);
    return false;
  }

  bool At(int idx, Value* out, int depth, const std::string& where) {
    idx = lua_absindex(L, idx);
    if (depth > 32) return Fail("table nested too deep (cycle?)");
    // Runs outside any pcall, one level per nesting: grow the stack without raising.
    if (!lua_checkstack(L, 4)) return Fail("out of Lua stack");
    switch (lua_type(L, idx)) {
      case LUA_TNIL:
        *out = Value();
        return true;
      case LUA_TBOOLEAN:
        *out = Value::OfBool(lua_toboolean(L, idx) != 0);
        return true;
      case LUA_TNUMBER:
        *out = Number(idx, where);
        return true;
      case LUA_TSTRING:
        *out = Value::OfString(LuaString(L, idx));
        return true;
      case LUA_TTABLE:
        return Table(idx, out, depth, where);
      default:
        return Fail(std::string("cannot write a ") + luaL_typename(L, idx) + " to JSON");
    }
  }

  Value Number(int idx, const std::string& where) {
    if (lua_isinteger(L, idx)) return Value::OfInteger(static_cast<int64_t>(lua_tointeger(L, idx)));
    const double v = lua_tonumber(L, idx);
    if (std::isfinite(v)) return Value::OfNumber(v);
    nonfinite->push_back(where);
    return Value();
  }

  // The table's keys as text; whether they are all integers, and how many.
  bool Keys(int idx, std::vector<std::string>* keys, bool* all_int) {
    *all_int = true;
    lua_pushnil(L);
    while (lua_next(L, idx)) {
      if (lua_type(L, -2) == LUA_TSTRING)
        keys->push_back(LuaString(L, -2));
      else if (lua_isinteger(L, -2))
        keys->push_back(std::to_string(lua_tointeger(L, -2)));
      else {
        lua_pop(L, 2);
        return Fail("table keys must be strings or integers");
      }
      *all_int &= lua_isinteger(L, -2) != 0;
      lua_pop(L, 1);
    }
    return true;
  }

  std::string ForcedType(int idx) {
    std::string forced;
    if (luaL_getmetafield(L, idx, "__jsontype") != LUA_TNIL) {
      if (lua_type(L, -1) == LUA_TSTRING) forced = lua_tostring(L, -1);
      lua_pop(L, 1);
    }
    return forced;
  }

  bool Table(int idx, Value* out, int depth, const std::string& where) {
    const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, idx));
    std::vector<std::string> keys;
    bool all_int = true;
    if (!Keys(idx, &keys, &all_int)) return false;
    const std::string forced = ForcedType(idx);
    const bool as_list = forced.empty() ? keys.size() == static_cast<size_t>(n) && all_int : forced == "array";
    return as_list ? List(idx, n, out, depth, where) : Map(idx, &keys, out, depth, where);
  }

  bool List(int idx, lua_Integer n, Value* out, int depth, const std::string& where) {
    *out = Value::EmptyList();
    for (lua_Integer k = 1; k <= n; ++k) {
      lua_rawgeti(L, idx, k);
      Value v;
      const bool ok = At(-1, &v, depth + 1, where + "[" + std::to_string(k) + "]");
      lua_pop(L, 1);
      if (!ok) return false;
      out->list.push_back(std::move(v));
    }
    return true;
  }

  bool Map(int idx, std::vector<std::string>* keys, Value* out, int depth, const std::string& where) {
    std::sort(keys->begin(), keys->end());
    *out = Value::EmptyMap();
    for (const std::string& k : *keys) {
      PushField(idx, k);
      Value v;
      const bool ok = At(-1, &v, depth + 1, where.empty() ? k : where + "." + k);
      lua_pop(L, 1);
      if (!ok) return false;
      out->Set(k, std::move(v));
    }
    return true;
  }

  // Keys were collected as text; integer keys are looked up as integers.
  void PushField(int idx, const std::string& k) {
    if (auto as_int = ParseInt(k)) {
      if (lua_rawgeti(L, idx, *as_int) != LUA_TNIL) return;
      lua_pop(L, 1);
    }
    lua_pushlstring(L, k.data(), k.size());
    lua_gettable(L, idx);
  }
};

}  // namespace

bool LuaToValue(lua_State* L, int idx, Value* out, std::vector<std::string>* nonfinite, std::string* error) {
  ValueWalk walk{L, nonfinite, error};
  return walk.At(idx, out, 0, "");
}

}  // namespace essaim
