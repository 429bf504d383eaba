// The Lua watchdog and sandbox (lua/host/lua_guard.h, docs/sandbox.md): budget, memory cap,
// wall clock, actuator checks, and what --sandbox leaves reachable.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>

#include "core/json.h"
#include "lua/host/watchdog.h"
#include "sim/run_end.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

SimOptions Sandboxed(long long budget = 1000000) {
  SimOptions so;
  so.lua.sandbox = true;
  so.lua.instruction_limit = so.lua.setup_instruction_limit = budget;
  return so;
}

/// Runs `script` as robot fb0 for one tick; returns its controller error ("" if none).
std::string StepError(const std::string& script, const SimOptions& so) {
  TempDir d;
  d.Write("c.lua", script);
  Scene s = Load(d, Experiment(FootBot("fb0", 0, 0, 0, "c"), WheelsController("c", "c.lua")), {}, so);
  if (!s.ok()) return "load failed: " + s.error;
  Step(*s.world);
  return s.world->controller_errors.empty() ? "" : s.world->controller_errors[0].message;
}

TEST(LuaSandbox, LeavesNoWayToFilesProcessesNativeCodeOrHooks) {
  std::string e = StepError(R"(
function step()
  assert(io == nil and os == nil and debug == nil and dofile == nil and loadfile == nil)
  assert(package.loaded.io == nil and package.loaded.os == nil and package.loaded.debug == nil)
  assert(package.loadlib == nil and package.cpath == "")
  assert(package.searchers[3] == nil and package.searchers[4] == nil and #package.searchers == 2)
  assert(not pcall(require, "os") and not pcall(require, "io") and not pcall(require, "debug"))
  -- Bytecode can crash the VM: load() takes text only.
  local ok, err = load(string.dump(function() return 1 end))
  assert(ok == nil and err:find("binary"), err)
  assert(load("return 2")() == 2)
end
)",
                            Sandboxed());
  EXPECT_EQ(e, "");
}

TEST(LuaSandbox, RequireLoadsLuaModulesAsTextOnly) {
  TempDir d;
  d.Write("helper.lua", "return {answer = 42}");
  d.Write("compiled.lua", std::string("\x1bLua\x54\x00", 6) + "not really bytecode");
  d.Write("c.lua", R"(
function step()
  assert(require("helper").answer == 42)
  local ok, err = pcall(require, "compiled")
  assert(not ok and err:find("attempt to load a binary chunk"), err)
  local ok2, err2 = pcall(require, "nowhere")
  assert(not ok2 and err2:find("module 'nowhere' not found"), err2)
end
)");
  Scene s = Load(d, Experiment(FootBot("fb0", 0, 0, 0, "c"), WheelsController("c", "c.lua")), {}, Sandboxed());
  ASSERT_TRUE(s.ok()) << s.error;
  Step(*s.world);
  EXPECT_TRUE(s.world->controller_errors.empty()) << s.world->controller_errors[0].message;
}

TEST(LuaSandbox, LoopFunctionsAreSandboxedToo) {
  TempDir d;
  d.Write("c.lua", "function step() end");
  d.Write("loop.lua", "function post_step() os.execute('true') end");
  Scene s = Load(d,
                 Experiment(FootBot("fb0", 0, 0, 0, "c"), WheelsController("c", "c.lua"), 10, 1,
                            "<loop_functions script=\"loop.lua\"/>"),
                 {}, Sandboxed());
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_EQ(Step(*s.world), StepStatus::Failed);
  EXPECT_NE(s.world->failure.find("attempt to index a nil value (global 'os')"), std::string::npos) << s.world->failure;
}

TEST(LuaSandbox, BudgetCoversCoroutines) {
  std::string e = StepError("function step() coroutine.wrap(function() while true do end end)() end", Sandboxed());
  EXPECT_NE(e.find("instruction budget exceeded (1000000 instructions per call"), std::string::npos) << e;
}

TEST(LuaSandbox, NestedPcallCannotSwallowTheStop) {
  std::string e = StepError(R"(
function step()
  while true do pcall(function() while true do pcall(function() while true do end end) end end) end
end)",
                            Sandboxed());
  EXPECT_NE(e.find("instruction budget exceeded"), std::string::npos) << e;
}

TEST(LuaWatchdog, OnByDefaultAndNotClearedByDebugSethook) {
  SimOptions so;
  so.lua.instruction_limit = so.lua.setup_instruction_limit = 1000000;
  // debug.sethook is refused outright (a loop calling it kept removing the hook)...
  std::string e = StepError("function step() debug.sethook() local x = 1 while x > 0 do x = x + 1 end end", so);
  EXPECT_NE(e.find("c.lua:1: debug.sethook is not available: the watchdog's hook cannot be replaced"),
            std::string::npos)
      << e;
  // ...and a script that catches the refusal is still stopped by its budget.
  e = StepError("function step() pcall(debug.sethook) local x = 1 while x > 0 do x = x + 1 end end", so);
  EXPECT_NE(e.find("c.lua:1: instruction budget exceeded (1000000 instructions per call"), std::string::npos) << e;
  EXPECT_NE(e.find("stack traceback"), std::string::npos) << e;
}

TEST(LuaWatchdog, ByDefaultCoversCoroutinesToo) {
  SimOptions so;
  so.lua.instruction_limit = so.lua.setup_instruction_limit = 1000000;
  for (const char* body :
       {"coroutine.wrap(function() while true do end end)()",
        "coroutine.resume(coroutine.create(function() while true do end end)) while true do end",
        "local co = coroutine.wrap(function() coroutine.yield(1) while true do end end) co() co()"}) {
    std::string e = StepError(std::string("function step() ") + body + " end", so);
    EXPECT_NE(e.find("instruction budget exceeded (1000000 instructions per call"), std::string::npos) << body << "\n"
                                                                                                       << e;
  }
}

TEST(LuaWatchdog, GuardedCoroutinesBehaveAsLuas) {
  std::string e = StepError(R"lua(
function step()
  local gen = coroutine.wrap(function(a) local b = coroutine.yield(a + 1) return b * 2 end)
  assert(gen(1) == 2 and gen(5) == 10)
  local ok, err = pcall(coroutine.wrap(function() error("boom") end))
  assert(not ok and err:find("^[^:]*c.lua:5: boom$"), err)
  local co = coroutine.create(function(x) return x, coroutine.isyieldable() end)
  local ok2, x, y = coroutine.resume(co, 7)
  assert(ok2 and x == 7 and y == true and coroutine.status(co) == "dead")
  assert(not pcall(coroutine.resume, 42))
  -- As Lua 5.4's auxwrap: a coroutine that dies by an error has its to-be-closed variables
  -- closed (an error there replaces the original), a dead one cannot be resumed, and a
  -- non-function is wrap's bad argument.
  local closed = false
  local dies = coroutine.wrap(function()
    local x <close> = setmetatable({}, {__close = function() closed = true end})
    error("boom", 0)
  end)
  local ok3, err3 = pcall(dies)
  assert(not ok3 and err3 == "boom" and closed, err3)
  local ok4, err4 = pcall(dies)
  assert(not ok4 and err4 == "cannot resume dead coroutine", err4)
  local replaced = coroutine.wrap(function()
    local x <close> = setmetatable({}, {__close = function() error("in close", 0) end})
    error("boom", 0)
  end)
  assert(select(2, pcall(replaced)) == "in close")
  local ok5, err5 = pcall(coroutine.wrap, 1)
  assert(err5 == "bad argument #1 to 'coroutine.wrap' (function expected, got number)", err5)
  assert(select(2, pcall(coroutine.wrap)) == "bad argument #1 to 'coroutine.wrap' (function expected, got no value)")
end
)lua",
                            SimOptions());
  EXPECT_EQ(e, "");
}

TEST(LuaWatchdog, NextCallStartsWithAFreshBudget) {
  TempDir d;
  // Each step uses ~60% of the budget: never stopped, however many steps.
  d.Write("c.lua", "function step() local s = 0 for i = 1, 200000 do s = s + i end end");
  SimOptions so = Sandboxed(1000000);
  Scene s = Load(d, Experiment(FootBot("fb0", 0, 0, 0, "c"), WheelsController("c", "c.lua")), {}, so);
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 5);
  EXPECT_TRUE(s.world->controller_errors.empty()) << s.world->controller_errors[0].message;
}

TEST(LuaWatchdog, WallClockBacksUpAnUnlimitedBudget) {
  SimOptions so;
  so.lua.instruction_limit = so.lua.setup_instruction_limit = 0;
  so.lua.wall_seconds = 0.3;
  std::string e = StepError("function step() while true do end end", so);
  EXPECT_NE(e.find("wall-clock limit exceeded (0.3 s per call)"), std::string::npos) << e;
}

TEST(LuaWatchdog, MemoryHogIsClosedAndFreedOthersUntouched) {
  TempDir d;
  d.Write("hog.lua", "function step() local t = {} while true do t[#t + 1] = string.rep('x', 100) .. #t end end");
  d.Write("good.lua", "function step() robot.wheels.set_velocity(5, 5) end");
  SimOptions so;
  so.lua.memory_limit = 8u << 20;
  Scene s = Load(d,
                 Experiment(FootBot("hog", 0, 0, 0, "h") + FootBot("good", 0, 1, 0, "g"),
                            WheelsController("h", "hog.lua") + WheelsController("g", "good.lua")),
                 {}, so);
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 10);
  ASSERT_EQ(s.world->controller_errors.size(), 1u);
  EXPECT_EQ(s.world->controller_errors[0].robot, "hog");
  EXPECT_NE(s.world->controller_errors[0].message.find("memory limit exceeded (8 MiB per Lua state"), std::string::npos)
      << s.world->controller_errors[0].message;
  EXPECT_EQ(LuaStateOf(s.world->controllers[0].get()), nullptr);
  EXPECT_EQ(s.world->controllers[0]->Memory().bytes, 0u);
  EXPECT_GT(s.world->physics.RobotPose(1).x, 0.03);  // 9 ticks at 5 cm/s
  Value metrics_tree;
  bool has = false;
  std::string err;
  EXPECT_TRUE(FinishRun(*s.world, &metrics_tree, &has, &err)) << err;  // destroy skips the closed state
}

// Filling the readings allocates (every received message is a fresh table): a state kept
// just under its limit, holding everything it got, runs out there, outside step(). It must
// stop alone with the limit named, not abort the process (it did: a Lua panic).
TEST(LuaWatchdog, MemoryLimitHitWhileFillingReadingsStopsThatRobotAlone) {
  TempDir d;
  d.Write("hog.lua", R"(
local keep, n, hog = {}, 0, nil
for i = 1, 20000 do keep[i] = false end  -- room for every message: storing one allocates nothing
function step()
  for i = 1, #robot.range_and_bearing do n = n + 1; keep[n] = robot.range_and_bearing[i] end
  if hog == nil and n > 0 then
    collectgarbage("collect")
    collectgarbage("stop")  -- nothing becomes garbage from here on anyway
    while collectgarbage("count") * 1024 < 8 * 1024 * 1024 - 2000 do hog = {hog} end
  end
end)");
  d.Write("talk.lua", "function step() robot.range_and_bearing.set_data(1, 7) robot.wheels.set_velocity(1, 1) end");
  auto rab_controller = [](const std::string& id, const std::string& script) {
    return "<lua_controller id=\"" + id +
           "\"><actuators><differential_steering implementation=\"default\"/>"
           "<range_and_bearing implementation=\"default\"/></actuators><sensors>"
           "<range_and_bearing implementation=\"medium\" medium=\"rab\"/></sensors><params script=\"" +
           script + "\"/></lua_controller>";
  };
  std::string bots = FootBot("hog", 0, 0, 0, "h");
  for (int k = 0; k < 4; ++k)
    bots += FootBot("t" + std::to_string(k), 0.5 * std::cos(k * 1.5), 0.5 * std::sin(k * 1.5), 0, "t");
  std::string xml = Experiment(bots, rab_controller("h", "hog.lua") + rab_controller("t", "talk.lua"));
  xml.replace(xml.find("<media/>"), 8, "<media><range_and_bearing id=\"rab\"/></media>");
  SimOptions so;
  so.lua.memory_limit = 8u << 20;
  Scene s = Load(d, xml, {}, so);
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 60);
  ASSERT_EQ(s.world->controller_errors.size(), 1u);
  const std::string& e = s.world->controller_errors[0].message;
  EXPECT_EQ(s.world->controller_errors[0].robot, "hog");
  EXPECT_NE(e.find("memory limit exceeded (8 MiB per Lua state"), std::string::npos) << e;
  EXPECT_NE(e.find("(filling its sensor readings)"), std::string::npos) << e;
  EXPECT_EQ(LuaStateOf(s.world->controllers[0].get()), nullptr);
  EXPECT_EQ(s.world->controllers[0]->Memory().bytes, 0u);
  for (int k = 1; k <= 4; ++k) EXPECT_TRUE(s.world->robots[k].controller_ok);
  EXPECT_EQ(s.world->tick, 60u);
}

// A controller's metamethod on a reading table runs Lua code while the readings are filled
// (lua_setfield honours __newindex once the field is gone): the watchdog covers it there too.
TEST(LuaWatchdog, EndlessMetamethodWhileFillingReadingsIsStopped) {
  TempDir d;
  d.Write("c.lua", R"(
function step()
  robot.wheels.velocity_left = nil
  setmetatable(robot.wheels, {__newindex = function() while true do end end})
end)");
  SimOptions so;
  so.lua.instruction_limit = so.lua.setup_instruction_limit = 1000000;
  d.Write("c2.lua", "function step() robot.wheels.set_velocity(5, 5) end");
  Scene s = Load(d,
                 Experiment(FootBot("fb0", 0, 0, 0, "c") + FootBot("fb1", 1, 0, 0, "c2"),
                            WheelsController("c", "c.lua") + WheelsController("c2", "c2.lua")),
                 {}, so);
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 5);
  ASSERT_EQ(s.world->controller_errors.size(), 1u);
  const std::string& e = s.world->controller_errors[0].message;
  EXPECT_EQ(s.world->controller_errors[0].robot, "fb0");
  EXPECT_NE(e.find("instruction budget exceeded (1000000 instructions per call"), std::string::npos) << e;
  EXPECT_NE(e.find("(filling its sensor readings)"), std::string::npos) << e;
  EXPECT_TRUE(s.world->robots[1].controller_ok);
  EXPECT_GT(s.world->physics.RobotPose(1).x, 1.01);  // fb1 drove on at 5 cm/s
}

TEST(LuaWatchdog, NonFiniteActuatorValuesAreErrorsNamingFunctionAndValue) {
  TempDir d;
  d.Write("c.lua", R"(
local function fails(f, ...)
  local ok, e = pcall(f, ...)
  assert(not ok, "accepted")
  return e
end
function step()
  assert(fails(robot.wheels.set_velocity, 0/0, 1):find("robot.wheels.set_velocity: argument #1 is nan"))
  assert(fails(robot.wheels.set_velocity, 1, -math.huge):find("argument #2 is %-inf"))
  assert(fails(robot.leds.set_all_colors, 1, 1/0, 1):find("robot.leds.set_all_colors%(%): argument #2 is inf"))
  assert(fails(robot.leds.set_single_color, 0/0, "red"):find("argument #1 is nan"))
  assert(fails(robot.range_and_bearing.set_data, 1, 0/0):find("set_data: argument #2 is nan"))
  assert(fails(robot.range_and_bearing.set_data, {1, 0/0, 3, 4, 5, 6, 7, 8, 9, 10}):find("element #2 is nan"))
  assert(fails(robot.distance_scanner.set_rpm, 1/0):find("set_rpm: argument #1 is inf"))
  assert(fails(robot.distance_scanner.set_angle, 0/0):find("set_angle: argument #1 is nan"))
  assert(fails(robot.turret.set_rotation, 0/0):find("robot.turret.set_rotation: argument #1 is nan"))
  robot.wheels.set_velocity(1e300, -1e300)  -- finite: clamped
end
)");
  std::string ctrl =
      "<lua_controller id=\"c\"><actuators><differential_steering implementation=\"default\"/>"
      "<leds implementation=\"default\" medium=\"leds\"/><range_and_bearing implementation=\"default\"/>"
      "<footbot_distance_scanner implementation=\"default\"/><footbot_turret implementation=\"default\"/></actuators>"
      "<sensors/><params script=\"c.lua\"/></lua_controller>";
  std::string xml = Experiment(FootBot("fb0", 0, 0, 0, "c"), ctrl);
  xml.replace(xml.find("<media/>"), 8, "<media><led id=\"leds\"/><range_and_bearing id=\"rab\"/></media>");
  Scene s = Load(d, xml);
  ASSERT_TRUE(s.ok()) << s.error;
  Step(*s.world);
  ASSERT_TRUE(s.world->controller_errors.empty()) << s.world->controller_errors[0].message;
  EXPECT_EQ(s.world->robots[0].cmd.wheel_left, 10.0);  // m/s, kMaxWheelSpeed
  EXPECT_EQ(s.world->robots[0].cmd.wheel_right, -10.0);
  RunTicks(*s.world, 3);
  EXPECT_TRUE(std::isfinite(s.world->physics.RobotPose(0).x));
  EXPECT_TRUE(std::isfinite(s.world->physics.RobotPose(0).yaw));
}

}  // namespace
}  // namespace essaim

namespace essaim {
namespace {
using namespace essaim::testing;

TEST(ErrorReports, IdenticalInputErrorsPrintOnceWithACount) {
  ErrorList e;
  for (int i = 0; i < 3; ++i) e.Add("a.argos", 35, "controller", "no controller with id 'x'");
  e.Add("a.argos", 40, "box", "size must be > 0");
  EXPECT_EQ(e.Format(),
            "a.argos:35: <controller>: no controller with id 'x' (3 times)\n"
            "a.argos:40: <box>: size must be > 0\n");
}

TEST(ErrorReports, InitErrorsArePrintedAndIdenticalOnesGrouped) {
  TempDir d;
  d.Write("c.lua", "function init()\n  error('bad init')\nend\nfunction step() end");
  d.Write("ok.lua", "function step() end");
  std::vector<std::string> printed;
  SimOptions so;
  so.log_sink = [&](char stream, const std::string& line, const LogOrigin&) {
    if (stream == 'E') printed.push_back(line);
  };
  std::string arena =
      FootBot("a", 0, 0, 0, "c") + FootBot("b", 0, 1, 0, "c") + FootBot("c", 0, 2, 0, "c") + FootBot("d", 1, 0, 0, "k");
  Scene s = Load(d, Experiment(arena, WheelsController("c", "c.lua") + WheelsController("k", "ok.lua")), {}, so);
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_EQ(s.world->controller_errors.size(), 3u);
  ASSERT_EQ(printed.size(), 1u);
  EXPECT_EQ(printed[0].rfind("robot a: ", 0), 0u) << printed[0];
  EXPECT_NE(printed[0].find("c.lua:2: bad init"), std::string::npos) << printed[0];
  EXPECT_NE(printed[0].find("(in init)\n(the same error in 2 more robots: b, c)"), std::string::npos) << printed[0];
}

}  // namespace
}  // namespace essaim

namespace essaim {
namespace {
using namespace essaim::testing;

TEST(LuaWatchdogDeathTest, StuckInsideACFunctionEndsTheProcessWithAMessage) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  // The run's watchdog reports the stuck call; ending the process is its owner's part,
  // as the CLI's: the message on stderr, exit 1.
  Watchdog watchdog([](const std::string& message) {
    std::fprintf(stderr, "essaim: %s\n", message.c_str());
    _exit(1);
  });
  SimOptions so;
  so.lua.instruction_limit = so.lua.setup_instruction_limit = 0;
  so.lua.wall_seconds = 0.2;
  so.lua.watchdog = &watchdog;
  // Backtracking over 12 lazy captures: one string.find call, far longer than a second.
  const char* script = "function step() string.find(string.rep('a', 60), '.-.-.-.-.-.-.-.-.-.-.-.-b') end";
  EXPECT_EXIT(StepError(script, so), ::testing::ExitedWithCode(1),
              "robot fb0: stuck for [0-9]+ s inside a C function called from Lua; stopping \\(exit 1\\)");
}

}  // namespace
}  // namespace essaim
