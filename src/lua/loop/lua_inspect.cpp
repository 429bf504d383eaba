#include "lua/loop/lua_inspect.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <lua.hpp>
#include <optional>
#include <utility>
#include <vector>

#include "core/strings.h"
#include "lua/robot/lua_math_types.h"

namespace essaim {

namespace {

// Globals every state has: the standard library and what essaim itself defines.
bool IsLibraryGlobal(const char* name) {
  static const char* const kNames[] = {"_G",   "_VERSION", "coroutine", "debug",   "io",
                                       "math", "os",       "package",   "string",  "table",
                                       "utf8", "robot",    "vector2",   "vector3", "quaternion"};
  for (const char* n : kNames)
    if (std::strcmp(n, name) == 0) return true;
  return false;
}

struct TreeWalk {
  lua_State* L;
  const LuaTreeLimits& limits;
  int budget;

  // The key at `idx` as a map key; false for keys that are neither strings nor numbers.
  static bool KeyText(lua_State* L, int idx, std::string* out) {
    int t = lua_type(L, idx);
    if (t == LUA_TSTRING) {
      size_t n = 0;
      const char* s = lua_tolstring(L, idx, &n);
      out->assign(s, n);
      return true;
    }
    if (t != LUA_TNUMBER) return false;
    if (lua_isinteger(L, idx))
      *out = std::to_string(lua_tointeger(L, idx));
    else {
      char text[32];
      std::snprintf(text, sizeof text, "%.17g", lua_tonumber(L, idx));
      *out = text;
    }
    return true;
  }

  Value At(int idx, int depth) {
    switch (lua_type(L, idx)) {
      case LUA_TNUMBER:
        if (lua_isinteger(L, idx)) return Value::OfInteger(static_cast<int64_t>(lua_tointeger(L, idx)));
        return Value::OfNumber(lua_tonumber(L, idx));
      case LUA_TBOOLEAN:
        return Value::OfBool(lua_toboolean(L, idx) != 0);
      case LUA_TSTRING: {
        size_t n = 0;
        const char* s = lua_tolstring(L, idx, &n);
        std::string text(s, std::min(n, limits.string_chars));
        return Value::OfString(n > limits.string_chars ? text + "..." : text);
      }
      case LUA_TTABLE:
        return depth >= limits.depth ? Value::OfString("{...}") : Table(idx, depth + 1, false);
      case LUA_TUSERDATA:
        return MathValue(idx);
      default:
        return Value::OfString(lua_typename(L, lua_type(L, idx)));
    }
  }

  // A vector or quaternion as its components; other userdata by type name.
  Value MathValue(int idx) {
    const char* names[4];
    double values[4];
    int n = MathTypeFields(L, idx, names, values);
    if (n == 0) return Value::OfString("userdata");
    Value out = Value::EmptyMap();
    for (int i = 0; i < n; ++i) out.Set(names[i], Value::OfNumber(values[i]));
    return out;
  }

  // Keys in a stable order (pairs() order changes from run to run): numbers by value first,
  // then names.
  static bool KeyBefore(const std::pair<std::string, Value>& a, const std::pair<std::string, Value>& b) {
    std::optional<long long> x = ParseInt(a.first), y = ParseInt(b.first);
    if (x && y) return *x < *y;
    if (x || y) return x.has_value();
    return a.first < b.first;
  }

  Value Table(int idx, int depth, bool globals) {
    Value out = Value::EmptyMap();
    if (!lua_checkstack(L, 4)) return out;
    idx = lua_absindex(L, idx);
    int more = 0;
    std::vector<std::pair<std::string, Value>> entries;
    std::string key;
    lua_pushnil(L);
    while (lua_next(L, idx) != 0) {
      bool skip =
          lua_type(L, -1) == LUA_TFUNCTION || !KeyText(L, -2, &key) || (globals && IsLibraryGlobal(key.c_str()));
      if (!skip && (static_cast<int>(entries.size()) >= limits.per_table || budget <= 0)) {
        ++more;
      } else if (!skip) {
        --budget;
        entries.emplace_back(key, At(-1, depth));
      }
      lua_pop(L, 1);
    }
    std::sort(entries.begin(), entries.end(), KeyBefore);
    for (auto& [k, v] : entries) out.Set(k, std::move(v));
    if (more > 0) out.Set("...", Value::OfString(std::to_string(more) + " more"));
    return out;
  }
};

}  // namespace

Value LuaGlobalsTree(lua_State* L, const LuaTreeLimits& limits) {
  if (!L) return Value::EmptyMap();
  TreeWalk walk{L, limits, limits.total};
  lua_rawgeti(L, LUA_REGISTRYINDEX, LUA_RIDX_GLOBALS);
  Value out = walk.Table(-1, 1, true);
  lua_pop(L, 1);
  return out;
}

Value LuaGlobalTree(lua_State* L, const char* name, const LuaTreeLimits& limits) {
  if (!L) return Value();
  TreeWalk walk{L, limits, limits.total};
  lua_rawgeti(L, LUA_REGISTRYINDEX, LUA_RIDX_GLOBALS);
  lua_pushstring(L, name);
  lua_rawget(L, -2);
  Value out = lua_type(L, -1) == LUA_TTABLE ? walk.Table(-1, 1, false) : Value();
  lua_pop(L, 2);
  return out;
}

}  // namespace essaim
