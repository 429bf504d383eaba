// The Lua side of essaim debug (lua/debug): breakpoints moved to lines with code, conditions
// that do not compile, frames and locals of a small script, stepping by depth, evaluation in
// a frame's scope.
#include "lua/debug/lua_debugger.h"

#include <gtest/gtest.h>

#include <functional>
#include <lua.hpp>

#include "lua/debug/chunk_lines.h"
#include "lua/debug/lua_inspect_frames.h"
#include "lua/host/lua_host.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

const char* kScript = R"(-- line 1: a comment

local function add(a, b)
  local sum = a + b
  return sum
end

function step()
  local x = 1
  local y = add(x, 2)
  x = x + y
  return x
end
)";

TEST(ChunkLines, BlankAndCommentLinesMoveToTheNextLineWithCodeInsideNestedFunctions) {
  std::set<int> lines;
  std::string error;
  ASSERT_TRUE(ActiveLinesOfText(kScript, "=test", &lines, &error)) << error;
  EXPECT_EQ(NextActiveLine(lines, 1), 4);  // the comment, then a definition with no instruction of its own
  EXPECT_EQ(NextActiveLine(lines, 4), 4);  // inside add(): only reachable in the dump
  EXPECT_EQ(NextActiveLine(lines, 7), 8);  // between the functions
  EXPECT_EQ(NextActiveLine(lines, 12), 12);
  EXPECT_EQ(NextActiveLine(lines, 99), 0);  // past the end
}

TEST(ChunkLines, AFileThatDoesNotCompileSaysWhy) {
  std::set<int> lines;
  std::string error;
  EXPECT_FALSE(ActiveLinesOfText("function (", "=bad", &lines, &error));
  EXPECT_NE(error.find("bad:1:"), std::string::npos) << error;
}

TEST(HitCondition, NumbersMeanFromTheNthHitOnAndPercentEveryNth) {
  bool passes = false;
  std::string error;
  ASSERT_TRUE(HitConditionPasses("3", 2, &passes, &error));
  EXPECT_FALSE(passes);
  ASSERT_TRUE(HitConditionPasses(">= 3", 4, &passes, &error));
  EXPECT_TRUE(passes);
  ASSERT_TRUE(HitConditionPasses("%2", 4, &passes, &error));
  EXPECT_TRUE(passes);
  EXPECT_FALSE(HitConditionPasses("often", 1, &passes, &error));
  EXPECT_NE(error.find("hitCondition"), std::string::npos);
}

/// Records each stop: the line, the frames' names, the locals of the innermost frame; then
/// resumes as `next_mode` says.
struct Recorder : DebugListener {
  LuaDebugger* debugger = nullptr;
  StepMode next_mode = StepMode::None;
  int stops_left = 10;
  std::vector<int> lines;
  std::vector<std::vector<std::string>> frames;
  std::vector<std::string> locals;
  std::vector<std::string> console;
  std::string evaluated;
  std::function<void(lua_State*)> on_stop;  // runs first at each stop

  void Stopped(int thread, lua_State* L, const StopInfo&) override {
    if (on_stop) on_stop(L);
    const std::vector<LuaFrame> f = LuaFrames(L, 0);
    lines.push_back(f.empty() ? 0 : f[0].line);
    std::vector<std::string> names;
    for (const LuaFrame& frame : f) names.push_back(frame.name);
    frames.push_back(names);
    locals.clear();
    for (const LuaVariable& v : FrameLocals(L, f[0].level)) locals.push_back(v.name + "=" + v.value);
    evaluated = EvaluateIn(L, f[0].level, "x * 10", false, 7).value.value;
    debugger->Resume(--stops_left > 0 ? next_mode : StepMode::None, thread, L);
  }
  void Console(const std::string& text) override { console.push_back(text); }
  bool Fired(const RunPosition&) override { return false; }
};

struct DebuggedState {
  TempDir dir;
  std::string path = dir.Write("c.lua", kScript);
  Recorder recorder;
  LuaDebugger debugger{&recorder};
  LuaGuard guard;
  lua_State* L = nullptr;

  DebuggedState() {
    recorder.debugger = &debugger;
    debugger.SetThreadIds({{"robot fb0", 2}});
    guard.name = "robot fb0";
    LuaOptions options;
    options.debugger = &debugger;
    L = NewGuardedState(&guard, options);
    OpenGuardedLibraries(L, false);
  }
  ~DebuggedState() { CloseGuardedState(&guard); }
  void RunStep() {
    ASSERT_EQ(luaL_dofile(L, path.c_str()), LUA_OK) << lua_tostring(L, -1);
    lua_getglobal(L, "step");
    ASSERT_EQ(lua_pcall(L, 0, 0, 0), LUA_OK) << lua_tostring(L, -1);
  }
  void Break(int line, const std::string& condition = "", const std::string& log = "") {
    LineBreakpoint bp;
    bp.line = line;
    bp.condition = condition;
    bp.log_message = log;
    const auto set = debugger.SetBreakpoints(path, {bp}, true, "");
    ASSERT_TRUE(set[0].verified) << set[0].message;
  }
};

TEST(LuaDebugger, ABreakpointStopsWithTheFramesAndLocalsOfTheScript) {
  DebuggedState s;
  s.Break(4);  // inside add(), called from step()
  s.RunStep();
  ASSERT_EQ(s.recorder.lines, std::vector<int>({4}));
  EXPECT_EQ(s.recorder.frames[0], std::vector<std::string>({"add", "step"}));
  EXPECT_EQ(s.recorder.locals, std::vector<std::string>({"a=1", "b=2"}));
}

TEST(LuaDebugger, StepOverStaysInTheFunctionAndStepInEntersTheCall) {
  DebuggedState over;
  over.recorder.next_mode = StepMode::Over;
  over.recorder.stops_left = 4;
  over.Break(9);
  over.RunStep();
  EXPECT_EQ(over.recorder.lines, std::vector<int>({9, 10, 11, 12}));
  EXPECT_EQ(over.recorder.evaluated, "40");  // x = 1 + 3 at line 12, seen through the frame's locals

  DebuggedState in;
  in.recorder.next_mode = StepMode::In;
  in.recorder.stops_left = 3;
  in.Break(10);
  in.RunStep();
  EXPECT_EQ(in.recorder.lines, std::vector<int>({10, 4, 5}));
}

TEST(LuaDebugger, ConditionsThatDoNotCompileAreRefusedAndThoseThatRaiseAreReported) {
  DebuggedState s;
  LineBreakpoint bad;
  bad.line = 9;
  bad.condition = "x ==";
  const auto set = s.debugger.SetBreakpoints(s.path, {bad}, true, "");
  EXPECT_FALSE(set[0].verified);
  EXPECT_EQ(set[0].message.rfind("condition: ", 0), 0u) << set[0].message;
  s.Break(10, "nothing.here > 1");
  s.RunStep();
  EXPECT_TRUE(s.recorder.lines.empty());
  ASSERT_EQ(s.recorder.console.size(), 1u);
  EXPECT_EQ(s.recorder.console[0].rfind("fb0 tick 0: condition error: ", 0), 0u) << s.recorder.console[0];
}

TEST(LuaDebugger, LogpointsInterpolateAndNeverStop) {
  DebuggedState s;
  s.Break(11, "", "x is {x}, tick {tick}");
  s.debugger.SetTick(42);
  s.RunStep();
  EXPECT_TRUE(s.recorder.lines.empty());
  EXPECT_EQ(s.recorder.console, std::vector<std::string>({"fb0 tick 42: x is 1, tick 42\n"}));
}

TEST(LuaDebugger, SetVariableChangesALocalOfTheStoppedFrame) {
  DebuggedState s;
  std::string error, shown;
  s.recorder.on_stop = [&](lua_State* L) {
    LuaVariable v;
    EXPECT_TRUE(SetVariableIn(L, VariableScope::Locals, 0, -1, "x", "x + 41", 0, &v, &error)) << error;
    shown = v.value;
  };
  s.recorder.stops_left = 1;
  s.Break(10);  // x is 1 there
  s.RunStep();
  EXPECT_EQ(shown, "42");
  EXPECT_EQ(s.recorder.evaluated, "420");  // the frame sees the new value
}

TEST(RunPosition, OrderIsTickThenWhoRunsThenFires) {
  EXPECT_TRUE((RunPosition{4, 9, 3}) < (RunPosition{5, 2, 1}));
  EXPECT_TRUE((RunPosition{5, 2, 7}) < (RunPosition{5, 3, 1}));
  EXPECT_TRUE((RunPosition{5, 3, 1}) < (RunPosition{5, 3, 2}));
  EXPECT_FALSE((RunPosition{5, 3, 2}) < (RunPosition{5, 3, 2}));
}

}  // namespace
}  // namespace essaim
