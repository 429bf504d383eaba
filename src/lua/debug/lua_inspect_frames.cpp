#include "lua/debug/lua_inspect_frames.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <lua.hpp>
#include <map>
#include <set>

namespace essaim {

namespace {
constexpr size_t kMaxShown = 200;  // characters of a string value shown

std::string Quoted(const char* s, size_t n) {
  std::string out = "\"";
  out.append(s, std::min(n, kMaxShown));
  if (n > kMaxShown) out += "...";
  return out + "\"";
}

// The value at `index` as a debugger shows it; its type name into *type. Runs __tostring.
std::string Describe(lua_State* L, int index, std::string* type) {
  index = lua_absindex(L, index);
  *type = luaL_typename(L, index);
  switch (lua_type(L, index)) {
    case LUA_TSTRING: {
      size_t n = 0;
      const char* s = lua_tolstring(L, index, &n);
      return Quoted(s, n);
    }
    case LUA_TTABLE:
      if (!luaL_getmetafield(L, index, "__tostring")) {
        const lua_Unsigned n = lua_rawlen(L, index);
        return n > 0 ? "table [" + std::to_string(n) + "]" : "table";
      }
      lua_pop(L, 1);
      break;
    default:
      break;
  }
  size_t n = 0;
  const char* s = luaL_tolstring(L, index, &n);
  std::string out(s ? s : "?", s ? std::min(n, kMaxShown) : 1);
  lua_pop(L, 1);
  return out;
}

// The key at `index` as a variable name: [1] for integers, the string itself.
std::string KeyName(lua_State* L, int index) {
  if (lua_type(L, index) == LUA_TSTRING) return lua_tostring(L, index);
  if (lua_isinteger(L, index)) return "[" + std::to_string(lua_tointeger(L, index)) + "]";
  std::string type;
  return "[" + Describe(L, index, &type) + "]";
}

// The variable for the value on top (popped).
LuaVariable TakeVariable(lua_State* L, std::string name) {
  LuaVariable v;
  v.name = std::move(name);
  v.value = Describe(L, -1, &v.type);
  if (lua_type(L, -1) == LUA_TTABLE)
    v.ref = luaL_ref(L, LUA_REGISTRYINDEX);
  else
    lua_pop(L, 1);
  return v;
}

bool Hidden(const char* name) { return name[0] == '('; }

// The global name of the function on top (popped): essaim calls step() and init() from C,
// where Lua's debug info has no name for them.
std::string GlobalNameOf(lua_State* L) {
  std::string found = "?";
  lua_rawgeti(L, LUA_REGISTRYINDEX, LUA_RIDX_GLOBALS);
  lua_pushnil(L);
  while (lua_next(L, -2)) {
    if (lua_type(L, -2) == LUA_TSTRING && lua_rawequal(L, -1, -4)) found = lua_tostring(L, -2);
    lua_pop(L, 1);
  }
  lua_pop(L, 2);
  return found;
}

// The function-name Lua's debug info gives, or what the frame is.
std::string FrameName(lua_State* L, lua_Debug& ar) {
  if (ar.name) return ar.name;
  if (ar.what && std::string(ar.what) == "main") return "main chunk";
  lua_getinfo(L, "f", &ar);
  return GlobalNameOf(L);
}

const std::set<std::string>& LibraryGlobals() {
  static const std::set<std::string> names = {
      "_G",     "_VERSION", "assert",   "collectgarbage", "coroutine", "debug",  "dofile",  "error",   "getmetatable",
      "io",     "ipairs",   "load",     "loadfile",       "math",      "next",   "os",      "package", "pairs",
      "pcall",  "print",    "rawequal", "rawget",         "rawlen",    "rawset", "require", "select",  "setmetatable",
      "string", "table",    "tonumber", "tostring",       "type",      "utf8",   "warn",    "xpcall",  "log",
      "logerr", "robot",    "vector2",  "vector3",        "quaternion"};
  return names;
}
}  // namespace

int FirstLuaLevel(lua_State* L, int from_level) {
  lua_Debug ar;
  for (int level = from_level; lua_getstack(L, level, &ar); ++level) {
    lua_getinfo(L, "S", &ar);
    if (ar.what[0] != 'C') return level;
  }
  return -1;
}

std::vector<LuaFrame> LuaFrames(lua_State* L, int from_level) {
  std::vector<LuaFrame> frames;
  lua_Debug ar;
  for (int level = from_level; lua_getstack(L, level, &ar); ++level) {
    lua_getinfo(L, "Sln", &ar);
    if (ar.what[0] == 'C') continue;
    LuaFrame f;
    f.level = level;
    f.name = FrameName(L, ar);
    if (ar.source[0] == '@') f.source = ar.source + 1;
    f.line = ar.currentline;
    frames.push_back(f);
  }
  return frames;
}

std::vector<LuaVariable> FrameLocals(lua_State* L, int level) {
  std::vector<LuaVariable> out;
  lua_Debug ar;
  if (!lua_getstack(L, level, &ar)) return out;
  for (int i = 1;; ++i) {
    const char* name = lua_getlocal(L, &ar, i);
    if (!name) break;
    if (Hidden(name)) {
      lua_pop(L, 1);
      continue;
    }
    out.push_back(TakeVariable(L, name));
  }
  for (int i = 1; lua_getlocal(L, &ar, -i); ++i) out.push_back(TakeVariable(L, "...[" + std::to_string(i) + "]"));
  return out;
}

std::vector<LuaVariable> FrameUpvalues(lua_State* L, int level) {
  std::vector<LuaVariable> out;
  lua_Debug ar;
  if (!lua_getstack(L, level, &ar)) return out;
  lua_getinfo(L, "f", &ar);
  const int fn = lua_gettop(L);
  for (int i = 1;; ++i) {
    const char* name = lua_getupvalue(L, fn, i);
    if (!name) break;
    if (std::string(name) == "_ENV" || !*name) {
      lua_pop(L, 1);
      continue;
    }
    out.push_back(TakeVariable(L, name));
  }
  lua_pop(L, 1);
  return out;
}

std::vector<LuaVariable> UserGlobals(lua_State* L) {
  std::vector<LuaVariable> out;
  lua_rawgeti(L, LUA_REGISTRYINDEX, LUA_RIDX_GLOBALS);
  const int g = lua_gettop(L);
  lua_pushnil(L);
  while (lua_next(L, g)) {
    const bool named = lua_type(L, -2) == LUA_TSTRING;
    if (!named || LibraryGlobals().count(lua_tostring(L, -2)) || lua_iscfunction(L, -1)) {
      lua_pop(L, 1);
      continue;
    }
    const std::string name = lua_tostring(L, -2);
    out.push_back(TakeVariable(L, name));
  }
  lua_pop(L, 1);
  std::sort(out.begin(), out.end(), [](const LuaVariable& a, const LuaVariable& b) { return a.name < b.name; });
  return out;
}

std::vector<LuaVariable> TableEntries(lua_State* L, int ref) {
  std::vector<LuaVariable> array, named;
  lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
  const int t = lua_gettop(L);
  if (lua_type(L, t) != LUA_TTABLE) {
    lua_pop(L, 1);
    return array;
  }
  const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, t));
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, t, i);
    array.push_back(TakeVariable(L, "[" + std::to_string(i) + "]"));
  }
  lua_pushnil(L);
  while (lua_next(L, t)) {
    if (lua_isinteger(L, -2) && lua_tointeger(L, -2) >= 1 && lua_tointeger(L, -2) <= n) {
      lua_pop(L, 1);
      continue;
    }
    const std::string name = KeyName(L, -2);
    named.push_back(TakeVariable(L, name));
  }
  lua_pop(L, 1);
  std::sort(named.begin(), named.end(), [](const LuaVariable& a, const LuaVariable& b) { return a.name < b.name; });
  array.insert(array.end(), named.begin(), named.end());
  return array;
}

int GlobalTableRef(lua_State* L, const char* name) {
  lua_rawgeti(L, LUA_REGISTRYINDEX, LUA_RIDX_GLOBALS);
  lua_getfield(L, -1, name);
  lua_remove(L, -2);
  if (lua_type(L, -1) != LUA_TTABLE) {
    lua_pop(L, 1);
    return -1;
  }
  return luaL_ref(L, LUA_REGISTRYINDEX);
}

void ReleaseRef(lua_State* L, int ref) {
  if (ref >= 0) luaL_unref(L, LUA_REGISTRYINDEX, ref);
}

// ---- evaluation: a chunk whose _ENV holds the frame's locals and upvalues, then globals

namespace {
// __index and __newindex of the environment: a name the frame declares (in `names`, upvalue 1)
// stays in the environment (even when nil), any other goes to the globals (upvalue 2).
int EnvIndex(lua_State* L) {
  lua_pushvalue(L, 2);
  if (lua_rawget(L, lua_upvalueindex(1)) != LUA_TNIL) return lua_pushnil(L), 1;
  lua_pushvalue(L, 2);
  lua_gettable(L, lua_upvalueindex(2));
  return 1;
}

int EnvNewIndex(lua_State* L) {
  lua_pushvalue(L, 2);
  if (lua_rawget(L, lua_upvalueindex(1)) != LUA_TNIL) {
    lua_settop(L, 3);
    lua_rawset(L, 1);
    return 0;
  }
  lua_settop(L, 3);
  lua_settable(L, lua_upvalueindex(2));
  return 0;
}

// env[name] = value on top (popped), and name declared.
void Declare(lua_State* L, int env, int names, const char* name) {
  lua_setfield(L, env, name);
  lua_pushboolean(L, 1);
  lua_setfield(L, names, name);
}

// The frame's upvalues then locals (inner declarations last, so they win) into env.
void CopyFrame(lua_State* L, lua_Debug* ar, int env, int names) {
  lua_getinfo(L, "f", ar);
  const int fn = lua_gettop(L);
  for (int i = 1;; ++i) {
    const char* name = lua_getupvalue(L, fn, i);
    if (!name) break;
    if (std::string(name) == "_ENV" || !*name)
      lua_pop(L, 1);
    else
      Declare(L, env, names, name);
  }
  lua_pop(L, 1);
  for (int i = 1;; ++i) {
    const char* name = lua_getlocal(L, ar, i);
    if (!name) break;
    if (Hidden(name))
      lua_pop(L, 1);
    else
      Declare(L, env, names, name);
  }
}

// What the chunk changed in env goes back into the frame's locals and upvalues.
void WriteBack(lua_State* L, lua_Debug* ar, int env) {
  std::map<std::string, int> locals;  // name -> the innermost local of that name
  for (int i = 1;; ++i) {
    const char* name = lua_getlocal(L, ar, i);
    if (!name) break;
    lua_pop(L, 1);
    if (!Hidden(name)) locals[name] = i;
  }
  for (const auto& [name, index] : locals) {
    lua_getfield(L, env, name.c_str());
    lua_getlocal(L, ar, index);
    const bool same = lua_rawequal(L, -1, -2);
    lua_pop(L, 1);
    if (same || !lua_setlocal(L, ar, index)) lua_pop(L, 1);
  }
  lua_getinfo(L, "f", ar);
  const int fn = lua_gettop(L);
  for (int i = 1;; ++i) {
    const char* name = lua_getupvalue(L, fn, i);
    if (!name) break;
    if (locals.count(name) || std::string(name) == "_ENV" || !*name) {
      lua_pop(L, 1);
      continue;
    }
    lua_getfield(L, env, name);
    const bool same = lua_rawequal(L, -1, -2);
    if (same || !lua_setupvalue(L, fn, i)) lua_pop(L, 1);
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
}

// The environment table for `level` (-1: globals only) pushed; its names table below it.
int PushEnvironment(lua_State* L, lua_Debug* ar, long long tick) {
  lua_newtable(L);  // names
  const int names = lua_gettop(L);
  lua_newtable(L);  // env
  const int env = lua_gettop(L);
  lua_rawgeti(L, LUA_REGISTRYINDEX, LUA_RIDX_GLOBALS);
  lua_pushliteral(L, "tick");
  if (lua_rawget(L, -2) == LUA_TNIL) {
    lua_pushinteger(L, static_cast<lua_Integer>(tick));
    Declare(L, env, names, "tick");
  }
  lua_pop(L, 2);
  if (ar) CopyFrame(L, ar, env, names);
  lua_createtable(L, 0, 2);
  lua_pushvalue(L, names);
  lua_rawgeti(L, LUA_REGISTRYINDEX, LUA_RIDX_GLOBALS);
  lua_pushcclosure(L, EnvIndex, 2);
  lua_setfield(L, -2, "__index");
  lua_pushvalue(L, names);
  lua_rawgeti(L, LUA_REGISTRYINDEX, LUA_RIDX_GLOBALS);
  lua_pushcclosure(L, EnvNewIndex, 2);
  lua_setfield(L, -2, "__newindex");
  lua_setmetatable(L, env);
  return env;
}

int LoadCode(lua_State* L, const std::string& code, bool statements) {
  const std::string as_return = "return " + code;
  int status = luaL_loadbufferx(L, as_return.data(), as_return.size(), "=evaluate", "t");
  if (status != LUA_OK && statements) {
    lua_pop(L, 1);
    status = luaL_loadbufferx(L, code.data(), code.size(), "=evaluate", "t");
  }
  return status;
}

// Evaluates `code`; on success leaves its first result (nil when none) on top, above what
// was there, and returns true; else pushes nothing. `had_result`: whether it returned any.
bool PushEvaluated(lua_State* L, int level, const std::string& code, bool statements, long long tick,
                   std::string* error, bool* had_result) {
  const int top = lua_gettop(L);
  lua_Debug ar;
  const bool frame = level >= 0 && lua_getstack(L, level, &ar);
  const int env = PushEnvironment(L, frame ? &ar : nullptr, tick);
  if (LoadCode(L, code, statements) != LUA_OK) {
    *error = lua_tostring(L, -1) ? lua_tostring(L, -1) : "does not compile";
    lua_settop(L, top);
    return false;
  }
  lua_pushvalue(L, env);
  lua_setupvalue(L, -2, 1);
  const int base = lua_gettop(L);
  if (lua_pcall(L, 0, LUA_MULTRET, 0) != LUA_OK) {
    *error = lua_tostring(L, -1) ? lua_tostring(L, -1) : "error (not a string)";
    lua_settop(L, top);
    return false;
  }
  *had_result = lua_gettop(L) >= base;
  if (!*had_result) lua_pushnil(L);
  if (frame) WriteBack(L, &ar, env);
  lua_pushvalue(L, base);
  lua_replace(L, top + 1);
  lua_settop(L, top + 1);
  return true;
}
}  // namespace

LuaEvalResult EvaluateIn(lua_State* L, int level, const std::string& code, bool statements, long long tick) {
  LuaEvalResult out;
  bool had_result = false;
  if (!PushEvaluated(L, level, code, statements, tick, &out.error, &had_result)) return out;
  out.ok = true;
  out.value = TakeVariable(L, "");
  if (!had_result) out.value.value = "", out.value.type = "";
  return out;
}

namespace {
// The index of the innermost local `name` of the frame at `ar`, or 0.
int LocalIndex(lua_State* L, lua_Debug* ar, const std::string& name) {
  int found = 0;
  for (int i = 1;; ++i) {
    const char* n = lua_getlocal(L, ar, i);
    if (!n) return found;
    lua_pop(L, 1);
    if (name == n) found = i;
  }
}

// Sets the variable to the value on top (popped); false when there is no such variable.
bool Assign(lua_State* L, VariableScope scope, int level, int ref, const std::string& name) {
  lua_Debug ar;
  if ((scope == VariableScope::Locals || scope == VariableScope::Upvalues) && !lua_getstack(L, level, &ar))
    return false;
  if (scope == VariableScope::Locals) {
    const int index = LocalIndex(L, &ar, name);
    return index > 0 && lua_setlocal(L, &ar, index);
  }
  if (scope == VariableScope::Upvalues) {
    lua_getinfo(L, "f", &ar);
    lua_insert(L, -2);
    for (int i = 1;; ++i) {
      const char* n = lua_getupvalue(L, -2, i);
      if (!n) break;
      lua_pop(L, 1);
      if (name == n) {
        lua_setupvalue(L, -2, i);
        lua_pop(L, 1);
        return true;
      }
    }
    lua_pop(L, 2);
    return false;
  }
  if (scope == VariableScope::Globals) {
    lua_setglobal(L, name.c_str());
    return true;
  }
  lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
  lua_insert(L, -2);
  if (name.size() > 2 && name.front() == '[' && name.back() == ']')
    lua_pushinteger(L, std::strtoll(name.c_str() + 1, nullptr, 10));
  else
    lua_pushstring(L, name.c_str());
  lua_insert(L, -2);
  lua_settable(L, -3);
  lua_pop(L, 1);
  return true;
}
}  // namespace

bool SetVariableIn(lua_State* L, VariableScope scope, int level, int ref, const std::string& name,
                   const std::string& value, long long tick, LuaVariable* result, std::string* error) {
  bool had_result = false;
  const int frame_level = scope == VariableScope::Locals || scope == VariableScope::Upvalues ? level : -1;
  if (!PushEvaluated(L, frame_level, value, false, tick, error, &had_result)) return false;
  lua_pushvalue(L, -1);
  if (!Assign(L, scope, level, ref, name)) {
    lua_pop(L, 1);
    *error = "no variable '" + name + "' there";
    return false;
  }
  *result = TakeVariable(L, name);
  return true;
}

bool EvaluateTruth(lua_State* L, int level, const std::string& code, long long tick, bool* truth, std::string* error) {
  bool had_result = false;
  if (!PushEvaluated(L, level, code, false, tick, error, &had_result)) return false;
  *truth = lua_toboolean(L, -1);
  lua_pop(L, 1);
  return true;
}

bool EvaluateText(lua_State* L, int level, const std::string& code, long long tick, std::string* text,
                  std::string* error) {
  bool had_result = false;
  if (!PushEvaluated(L, level, code, false, tick, error, &had_result)) return false;
  size_t n = 0;
  const char* s = luaL_tolstring(L, -1, &n);
  text->assign(s ? s : "", s ? n : 0);
  lua_pop(L, 2);
  return true;
}

bool CompilesAsExpression(lua_State* L, const std::string& expression, std::string* error) {
  const std::string code = "return (" + expression + "\n)";
  const bool ok = luaL_loadbufferx(L, code.data(), code.size(), "=condition", "t") == LUA_OK;
  if (!ok) *error = lua_tostring(L, -1) ? lua_tostring(L, -1) : "does not compile";
  lua_pop(L, 1);
  return ok;
}

}  // namespace essaim
