// A stopped Lua state seen by a debugger: its frames, the variables of a frame (locals,
// upvalues), globals and tables one level at a time, expressions evaluated in a frame's
// scope, and values changed. Everything runs on the state's own thread while it is stopped
// (inside a hook) or idle between calls.
#pragma once
#include <string>
#include <vector>

struct lua_State;

namespace essaim {

/// One Lua function on the stack, innermost first.
struct LuaFrame {
  int level = 0;       // lua_getstack's level
  std::string name;    // as Lua's debug info names it ("step", "?" when unknown)
  std::string source;  // the file's path ("" for C functions and strings)
  int line = 0;
};

/// One variable as a debugger shows it. `ref` >= 0 is a registry reference to the table
/// it holds (to expand later: release with ReleaseRef), else -1.
struct LuaVariable {
  std::string name;
  std::string value;
  std::string type;
  int ref = -1;
};

/// The Lua frames of L from `from_level` on (C functions skipped).
std::vector<LuaFrame> LuaFrames(lua_State* L, int from_level);

/// The first level at or above `from_level` that runs a Lua function; -1 when none.
int FirstLuaLevel(lua_State* L, int from_level);

/// Locals of the frame at `level` in declaration order (temporaries hidden), then its varargs
/// as ...[1], ...[2].
std::vector<LuaVariable> FrameLocals(lua_State* L, int level);
/// Upvalues of the function at `level` (_ENV hidden).
std::vector<LuaVariable> FrameUpvalues(lua_State* L, int level);
/// The state's globals, without the standard libraries, essaim's own functions and `robot`.
std::vector<LuaVariable> UserGlobals(lua_State* L);
/// The entries of the table `ref` (a registry reference): array part first, in order, then
/// the other keys sorted by name.
std::vector<LuaVariable> TableEntries(lua_State* L, int ref);
/// A registry reference to the global `name` when it is a table, else -1.
int GlobalTableRef(lua_State* L, const char* name);
void ReleaseRef(lua_State* L, int ref);

/// The result of evaluating an expression: its text, type and, for a table, a reference.
struct LuaEvalResult {
  bool ok = false;
  LuaVariable value;  // name unused
  std::string error;
};

/// Evaluates `code` in L with the locals and upvalues of the frame at `level` visible
/// (level < 0: globals only), then globals; `tick` is visible as a name when the state has no
/// global `tick`. `statements`: `code` may be a statement ("x = 3"); assignments to a local
/// or upvalue change it. Hooks must not stop inside (the debugger's own flag).
LuaEvalResult EvaluateIn(lua_State* L, int level, const std::string& code, bool statements, long long tick);

/// The truth of an expression (a breakpoint's condition) in that scope; false with `error`
/// when it does not compile or raises.
bool EvaluateTruth(lua_State* L, int level, const std::string& code, long long tick, bool* truth, std::string* error);
/// An expression's value as tostring() gives it (a logpoint's {expr}).
bool EvaluateText(lua_State* L, int level, const std::string& code, long long tick, std::string* text,
                  std::string* error);

/// Whether `expression` compiles as an expression; else false with Lua's message.
bool CompilesAsExpression(lua_State* L, const std::string& expression, std::string* error);

/// Which variable to set: the scope it is listed in and, for a table, its reference.
enum class VariableScope { Locals, Upvalues, Globals, Table };
/// Sets `name` in `scope` (level for locals and upvalues, ref for a table) to the value of
/// the Lua expression `value` (evaluated in the frame's scope). The new value's text, or
/// false with `error`.
bool SetVariableIn(lua_State* L, VariableScope scope, int level, int ref, const std::string& name,
                   const std::string& value, long long tick, LuaVariable* result, std::string* error);

}  // namespace essaim
