// The Lua host: the robot table, lifecycle, errors, latency, require, logs.
#include <gtest/gtest.h>

#include <cmath>

#include "core/json.h"
#include "sim/run_end.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

struct Logged {
  std::vector<std::pair<char, std::string>> lines;
};

Scene LoadWithLog(const TempDir& d, const std::string& xml, Logged* log, LoadOptions lo = {}) {
  SimOptions so;
  so.log_sink = [log](char s, const std::string& l, const LogOrigin&) { log->lines.push_back({s, l}); };
  return Load(d, xml, lo, so);
}

TEST(LuaHost, RobotTableIdParamsAndRandom) {
  TempDir d;
  d.Write("c.lua", R"(
function init()
  assert(robot.id == "fb7", robot.id)
  assert(robot.params.speed == "12.5" and type(robot.params.speed) == "string")
  assert(robot.params.script == "c.lua")
  for i = 1, 1000 do
    local u = robot.random.uniform(); assert(u >= 0 and u <= 1)
    local v = robot.random.uniform(2, 3); assert(v >= 2 and v <= 3)
    local k = robot.random.uniform_int(1, 4); assert(math.type(k) == "integer" and k >= 1 and k <= 3)
    assert(type(robot.random.bernoulli(0.5)) == "boolean")
    assert(math.type(robot.random.poisson(2)) == "integer")
  end
  assert(robot.wheels.axis_length == 14)
  log("init ok", 3, 0.5, true)
end
function step() end
)");
  Logged log;
  Scene s = LoadWithLog(
      d, Experiment(FootBot("fb7", 0, 0, 0, "c"), WheelsController("c", "c.lua", "", "speed=\"12.5\"")), &log);
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_TRUE(s.world->controller_errors.empty()) << s.world->controller_errors[0].message;
  RunTicks(*s.world, 1);
  ASSERT_FALSE(log.lines.empty());
  EXPECT_EQ(log.lines[0].second, "init ok30.51");  // ARGoS's log: no separator, booleans 1/0
}

TEST(LuaHost, PositioningGivesPositionAndQuaternionWithAngleAxisFields) {
  TempDir d;
  d.Write("c.lua", R"(
function init()
  local p = robot.positioning.position
  assert(math.abs(p.x - 1.5) < 1e-6 and math.abs(p.y + 2) < 1e-6, tostring(p))
  local q = robot.positioning.orientation
  local yaw = q:toeulerangles()
  assert(math.abs(yaw - math.pi / 2) < 1e-6, yaw)
  assert(math.abs(q.angle - math.pi / 2) < 1e-6 and q.axis.z > 0.99)   -- old-style fields
  local a, axis = q:toangleaxis()
  assert(math.abs(a - math.pi / 2) < 1e-6 and math.abs(axis.z - 1) < 1e-6)
  local v = vector3(1, 0, 0); v:rotate(q)
  assert(math.abs(v.x) < 1e-6 and math.abs(v.y - 1) < 1e-6)
  local w = vector2(3, 4); assert(w:length() == 5)
  last = p
end
function step()
  assert(robot.positioning.position ~= last or true)
  kept = last   -- a kept reference must not change under the controller
  assert(math.abs(kept.x - 1.5) < 1e-6)
end
)");
  Scene s = Load(d, Experiment(FootBot("fb0", 1.5, -2, 90, "c"), WheelsController("c", "c.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 3);
  ASSERT_TRUE(s.world->controller_errors.empty()) << s.world->controller_errors[0].message;
}

TEST(LuaHost, CommandsActOneTickLater) {
  TempDir d;
  // No command in init: the first step() sets the speed, which acts during tick 2.
  d.Write("c.lua", R"(
function step()
  ticks = (ticks or 0) + 1
  if ticks == 1 then
    assert(robot.wheels.velocity_left == 0)
    robot.wheels.set_velocity(10, 10)
  elseif ticks == 2 then
    assert(robot.wheels.velocity_left == 10, robot.wheels.velocity_left)   -- reports last command
    assert(math.abs(robot.wheels.distance_left - 1) < 1e-9)                -- cm in one 0.1 s tick
  end
end
)");
  Scene s = Load(d, Experiment(FootBot("fb0", 0, 0, 0, "c"), WheelsController("c", "c.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  Step(*s.world);
  EXPECT_NEAR(s.world->physics.RobotPose(0).x, 0, 1e-9);
  Step(*s.world);
  EXPECT_GT(s.world->physics.RobotPose(0).x, 0.005);
  EXPECT_TRUE(s.world->controller_errors.empty()) << s.world->controller_errors[0].message;
}

TEST(LuaHost, RequireFindsModulesBesideTheScript) {
  TempDir d;
  system(("mkdir -p " + d.path() + "/ctrl/lib").c_str());
  d.Write("ctrl/lib/helper.lua", "local M = {} function M.double(x) return 2 * x end return M");
  d.Write("ctrl/main.lua",
          "local h = require 'lib.helper'\nfunction init() assert(h.double(21) == 42) end\nfunction step() end");
  Scene s = Load(d, Experiment(FootBot("fb0", 0, 0, 0, "c"), WheelsController("c", "ctrl/main.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_TRUE(s.world->controller_errors.empty());
}

TEST(LuaHost, RuntimeErrorStopsOneRobotAndNamesIt) {
  TempDir d;
  d.Write("c.lua", R"(function init() robot.wheels.set_velocity(10, 10) end
function step()
  if robot.id == "bad" then
    local t = nil
    return t.field   -- line 5
  end
end
)");
  std::string arena = FootBot("good", 0, 0, 0, "c") + FootBot("bad", 0, 1, 0, "c");
  Logged log;
  Scene s = LoadWithLog(d, Experiment(arena, WheelsController("c", "c.lua")), &log);
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 20);
  ASSERT_EQ(s.world->controller_errors.size(), 1u);
  const ControllerError& e = s.world->controller_errors[0];
  EXPECT_EQ(e.robot, "bad");
  EXPECT_EQ(e.tick, 1u);
  EXPECT_NE(e.message.find("robot bad: "), std::string::npos) << e.message;
  EXPECT_NE(e.message.find("c.lua:5:"), std::string::npos) << e.message;
  EXPECT_NE(e.message.find("stack traceback"), std::string::npos) << e.message;
  // The broken robot stopped (wheels zeroed from tick 2); the good one went on.
  EXPECT_LT(s.world->physics.RobotPose(1).x, 0.02);
  EXPECT_GT(s.world->physics.RobotPose(0).x, 0.15);
}

TEST(LuaHost, StrictModeEndsTheRunAtTheFirstError) {
  TempDir d;
  d.Write("c.lua", "function step() error('boom') end");
  SimOptions so;
  so.strict = true;
  Scene s = Load(d, Experiment(FootBot("fb0", 0, 0, 0, "c"), WheelsController("c", "c.lua")), {}, so);
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_EQ(Step(*s.world), StepStatus::Failed);
  EXPECT_NE(s.world->failure.find("boom"), std::string::npos);
}

TEST(LuaHost, SyntaxErrorFailsTheLoadNamingRobotFileAndLine) {
  TempDir d;
  d.Write("c.lua", "function step()\n  x = = 1\nend\n");
  Scene s = Load(d, Experiment(FootBot("fb0", 0, 0, 0, "c"), WheelsController("c", "c.lua")));
  EXPECT_FALSE(s.world);
  EXPECT_NE(s.error.find("robot fb0: "), std::string::npos) << s.error;
  EXPECT_NE(s.error.find("c.lua:2:"), std::string::npos) << s.error;
}

TEST(LuaHost, LogsComeOutInRobotOrderWhateverTheThreads) {
  TempDir d;
  d.Write("c.lua", "function step() log(robot.id) end");
  std::string arena;
  for (int i = 0; i < 8; ++i) arena += FootBot("r" + std::to_string(i), i - 4, 0, 0, "c");
  LoadOptions lo;
  lo.threads = 3;
  Logged log;
  Scene s = LoadWithLog(d, Experiment(arena, WheelsController("c", "c.lua")), &log, lo);
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_EQ(s.world->threads, 3);
  RunTicks(*s.world, 2);
  ASSERT_EQ(log.lines.size(), 16u);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(log.lines[i].second, "r" + std::to_string(i % 8));
}

TEST(LuaHost, MathRandomIsSeededFromTheExperiment) {
  TempDir d;
  d.Write("c.lua", "function init() log(math.random(1, 1000000)) end function step() end");
  auto first = [&](int seed) {
    Logged log;
    Scene s = LoadWithLog(d, Experiment(FootBot("fb0", 0, 0, 0, "c"), WheelsController("c", "c.lua"), 10, seed), &log);
    EXPECT_TRUE(s.ok()) << s.error;
    Step(*s.world);
    return log.lines.empty() ? std::string() : log.lines[0].second;
  };
  EXPECT_EQ(first(3), first(3));
  EXPECT_NE(first(3), first(4));
}

TEST(LuaHost, SandboxDropsIoAndOs) {
  TempDir d;
  d.Write("c.lua", "function init() assert(io == nil and os == nil) end function step() end");
  SimOptions so;
  so.lua.sandbox = true;
  Scene s = Load(d, Experiment(FootBot("fb0", 0, 0, 0, "c"), WheelsController("c", "c.lua")), {}, so);
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_TRUE(s.world->controller_errors.empty());
}

TEST(LuaHost, SandboxStopsARunawayStep) {
  TempDir d;
  d.Write("c.lua", "function step() while true do end end");
  SimOptions so;
  so.lua.sandbox = true;
  so.lua.instruction_limit = so.lua.setup_instruction_limit = 100000;
  Scene s = Load(d, Experiment(FootBot("fb0", 0, 0, 0, "c"), WheelsController("c", "c.lua")), {}, so);
  ASSERT_TRUE(s.ok()) << s.error;
  Step(*s.world);
  ASSERT_EQ(s.world->controller_errors.size(), 1u);
  EXPECT_NE(s.world->controller_errors[0].message.find("instruction budget exceeded (100000 instructions per call"),
            std::string::npos)
      << s.world->controller_errors[0].message;
}

TEST(LoopFunctions, HooksSeeRobotsAndProduceMetricsAndSeries) {
  TempDir d;
  d.Write("c.lua", "function init() robot.wheels.set_velocity(10, 10) end function step() end");
  d.Write("loop.lua", R"(
function init() started = #experiment.robots end
function post_step()
  if experiment.tick % 5 == 0 then
    local x = experiment.robots[1]:position()
    experiment.timeseries({{"tick", experiment.tick}, {"x", x}})
  end
  if experiment.tick == 7 then experiment.robots[2]:kill() end
end
function is_experiment_finished() return experiment.tick >= 20 end
function post_experiment()
  return {robots = started, id = experiment.robots[1].id, alive2 = experiment.robots[2]:alive(),
          label = experiment.params.label, list = {1, 2, 3}}
end
)");
  std::string arena = FootBot("a", 0, 0, 0, "c") + FootBot("b", 0, 1, 0, "c");
  Scene s = Load(d, Experiment(arena, WheelsController("c", "c.lua"), 1000, 1,
                               "<loop_functions script=\"loop.lua\" label=\"hello\"/>"));
  ASSERT_TRUE(s.ok()) << s.error;
  StepStatus st;
  while ((st = Step(*s.world)) == StepStatus::Running) {
  }
  EXPECT_EQ(st, StepStatus::Finished);
  EXPECT_EQ(s.world->tick, 20u);
  EXPECT_FALSE(s.world->robots[1].alive);
  double xb = s.world->physics.RobotPose(1).x;
  EXPECT_LT(xb, 0.08);  // killed at tick 7: braked since
  Value metrics_tree;
  bool has = false;
  std::string err;
  ASSERT_TRUE(FinishRun(*s.world, &metrics_tree, &has, &err)) << err;
  Json metrics = ToJson(metrics_tree);
  ASSERT_TRUE(has);
  EXPECT_EQ(
      DumpJson(metrics),
      "{\n  \"alive2\": false,\n  \"id\": \"a\",\n  \"label\": \"hello\",\n  \"list\": [\n    1,\n    2,\n    3\n  ],\n"
      "  \"robots\": 2\n}\n");
  const Timeseries& ts = s.world->loop_functions.Series();
  ASSERT_EQ(ts.columns.size(), 2u);
  ASSERT_EQ(ts.rows.size(), 4u);
  EXPECT_EQ(ts.rows[3][0], 20);
}

}  // namespace
}  // namespace essaim

namespace essaim {
namespace {
using namespace essaim::testing;

// A loop-functions script `body` run with one robot; returns the run's failure text.
std::string LoopFailure(const std::string& body, const std::string& floor = "") {
  TempDir d;
  d.Write("c.lua", "function step() end");
  d.Write("loop.lua", body);
  Scene s = Load(d, Experiment(floor + FootBot("fb0", 0, 0, 0, "c"), WheelsController("c", "c.lua"), 100, 1,
                               "<loop_functions script=\"loop.lua\"/>"));
  if (!s.ok()) return s.error;
  if (!s.world->failure.empty()) return s.world->failure;  // init(), or the floor drawn after it
  for (int i = 0; i < 5; ++i)
    if (Step(*s.world) == StepStatus::Failed) return s.world->failure;
  return "";
}

TEST(LoopFunctions, ErrorsNameTheHookAndTheLine) {
  std::string f = LoopFailure("function post_step()\n  error('rule broken')\nend\n");
  EXPECT_NE(f.find("loop functions (post_step): "), std::string::npos) << f;
  EXPECT_NE(f.find("loop.lua:2: rule broken"), std::string::npos) << f;
}

// Used to be a Lua panic (exit 134): the host set experiment.tick through the global.
TEST(LoopFunctions, RebindingExperimentOrMetatablesOnGlobalsCannotCrashTheHost) {
  EXPECT_EQ(LoopFailure("function pre_step() experiment = nil end"), "");
  EXPECT_EQ(LoopFailure("function pre_step() experiment = 5 end"), "");
  EXPECT_EQ(LoopFailure("function init() setmetatable(experiment, {__newindex = function() error('no') end}) end"), "");
  EXPECT_EQ(LoopFailure("function init() setmetatable(_G, {__index = function() error('no') end}) end"), "");
  // The script's own use of the rebound global is an ordinary, reported error.
  std::string f =
      LoopFailure("function pre_step() experiment = nil end\nfunction post_step() return experiment.tick end");
  EXPECT_NE(f.find("loop functions (post_step): "), std::string::npos) << f;
}

TEST(LoopFunctions, SetPoseRefusesNonFiniteValues) {
  for (const char* v : {"0/0, 0, 0", "1/0, 0", "0, 0, -1/0"}) {
    std::string f = LoopFailure(std::string("function pre_step() experiment.robots[1]:set_pose(") + v + ") end");
    EXPECT_NE(f.find("set_pose: x, y and yaw must be finite numbers"), std::string::npos) << v << ": " << f;
  }
}

TEST(LoopFunctions, HandleMisuseIsALuaError) {
  std::string f = LoopFailure("function pre_step() experiment.robots[1].position(42) end");
  EXPECT_NE(f.find("position: entity handle expected"), std::string::npos) << f;
  f = LoopFailure("function pre_step() experiment.robots[1]:set_battery(2) end");
  EXPECT_NE(f.find("set_battery: charge must be in [0, 1]"), std::string::npos) << f;
  f = LoopFailure("function pre_step() experiment.robots[1]:led(14) end");
  EXPECT_NE(f.find("led index must be 1..13"), std::string::npos) << f;
}

TEST(LoopFunctions, TimeseriesColumnsMustStayTheSame) {
  std::string f = LoopFailure(
      "function post_step()\n"
      "  if experiment.tick == 1 then experiment.timeseries({{'tick', 1}, {'a', 2}})\n"
      "  else experiment.timeseries({{'tick', 2}, {'b', 3}}) end\n"
      "end\n");
  EXPECT_NE(f.find("timeseries: column 2 is 'b', expected 'a'"), std::string::npos) << f;
}

// The sanitizer build found the half-built row of a refused timeseries() call leaking
// (luaL_error jumps over C++ destructors); a refused first row also left its first
// columns behind, so every later good row was refused too.
TEST(LoopFunctions, ARefusedTimeseriesRowLeavesNothingBehind) {
  std::string f = LoopFailure(
      "function post_step()\n"
      "  if experiment.tick == 1 then assert(not pcall(experiment.timeseries, {{'tick', 1}, {'a'}})) end\n"
      "  experiment.timeseries({{'tick', experiment.tick}, {'b', 2}})\n"
      "end\n");
  EXPECT_EQ(f, "");
}

TEST(LoopFunctions, FloorColorMustReturnAColour) {
  const std::string floor = "<floor id=\"f\" source=\"loop_functions\" pixels_per_meter=\"2\"/>";
  std::string f = LoopFailure("function floor_color(x, y) return 'plaid' end", floor);
  EXPECT_NE(f.find("floor_color(x, y) must return r, g, b (0-255) or a colour name"), std::string::npos) << f;
  f = LoopFailure("function init() end", floor);
  EXPECT_NE(f.find("define no floor_color(x, y)"), std::string::npos) << f;
}

TEST(LuaHost, AScriptWithoutStepFailsTheRun) {
  // It would stand still all run: the run fails (ARGoS logs it and goes on).
  TempDir d;
  d.Write("c.lua", "function init() end");
  Scene s =
      Load(d, Experiment(FootBot("fb0", 0, 0, 0, "c") + FootBot("fb1", 1, 0, 0, "c"), WheelsController("c", "c.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_NE(s.world->failure.find("robot fb0: "), std::string::npos) << s.world->failure;
  EXPECT_NE(s.world->failure.find("c.lua: no global function 'step' after init() (nor in 1 more robots)"),
            std::string::npos)
      << s.world->failure;
}

TEST(LuaHost, StepMayBeDefinedByInit) {
  TempDir d;
  d.Write("c.lua", "function init() step = function() robot.wheels.set_velocity(1, 1) end end");
  Scene s = Load(d, Experiment(FootBot("fb0", 0, 0, 0, "c"), WheelsController("c", "c.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_EQ(s.world->failure, "");
  Step(*s.world);
  EXPECT_TRUE(s.world->controller_errors.empty());
}

}  // namespace
}  // namespace essaim
