// The bare-Lua floor: a controller replayed in a BareController on the readings of
// a real run must compute exactly what it computed in the run (same readings, same
// robot.random stream), and MeasureBareFloor must time every robot-step.
#include "sim/bare_floor.h"

#include <gtest/gtest.h>

#include <lua.hpp>

#include "lua/robot/bare_controller.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

// Folds every reading it sees (proximity, RAB messages and their bytes, position, scanner)
// and robot.random into a global, and drives its actuators from them.
const char* kChecksum = R"(
sum, messages = 0, 0
function init() sum = robot.positioning.position.x end
function step()
  local s = 0
  for i = 1, 24 do s = s + robot.proximity[i].value * i end
  for _, m in ipairs(robot.range_and_bearing) do
    s = s + m.range + 3 * m.horizontal_bearing + m.data[1] + 7 * m.data[2]
    messages = messages + 1
  end
  for _, r in ipairs(robot.distance_scanner.short_range) do s = s + r.angle + r.distance end
  s = s + robot.positioning.position.x + 2 * robot.positioning.position.y + robot.random.uniform()
  sum = sum * 0.5 + s
  robot.wheels.set_velocity(5 + 10 * robot.random.uniform(), 8)
  robot.range_and_bearing.set_data(1, math.floor(robot.random.uniform() * 255))
  robot.range_and_bearing.set_data(2, math.random(0, 255))
  robot.distance_scanner.set_rpm(60)
end
)";

std::string Controller() {
  return "<lua_controller id=\"c\"><actuators><differential_steering implementation=\"default\"/>"
         "<footbot_distance_scanner implementation=\"default\"/><range_and_bearing implementation=\"default\"/>"
         "</actuators><sensors><positioning implementation=\"default\"/>"
         "<footbot_proximity implementation=\"default\" show_rays=\"false\"/>"
         "<footbot_distance_scanner implementation=\"rot_z_only\" show_rays=\"false\"/>"
         "<range_and_bearing implementation=\"medium\" medium=\"rab\" show_rays=\"false\"/>"
         "</sensors><params script=\"checksum.lua\"/></lua_controller>";
}

std::string Scenario() {
  std::string arena;
  for (int i = 0; i < 6; ++i) arena += FootBot("fb" + std::to_string(i), 0.3 * (i % 3), 0.3 * (i / 3), 40.0 * i, "c");
  arena += Box("wall", 0.3, 0.6, 1.0, 0.05, 0.5);
  std::string xml = Experiment(arena, Controller(), 30);
  xml.replace(xml.find("<media/>"), 8, "<media><range_and_bearing id=\"rab\"/></media>");
  return xml;
}

double Global(lua_State* L, const char* name) {
  lua_getglobal(L, name);
  const double v = lua_tonumber(L, -1);
  lua_pop(L, 1);
  return v;
}

void ExpectReplayComputesWhatTheRunComputed(BareAllocator allocator) {
  TempDir d;
  d.Write("checksum.lua", kChecksum);
  Scene s = Load(d, Scenario());
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  const size_t n = s.model->robots.size();
  std::vector<std::unique_ptr<BareController>> bare;
  std::string error;
  for (size_t i = 0; i < n; ++i) {
    bare.push_back(std::make_unique<BareController>());
    ASSERT_TRUE(
        bare[i]->Load(*s.model, s.model->robots[i], static_cast<int>(i), s.model->experiment.seed, &error, allocator))
        << error;
    bare[i]->PushReadings(w.robots[i]);
    ASSERT_TRUE(bare[i]->CallInit(&error)) << error;
  }
  for (int t = 0; t < 30; ++t) {
    ASSERT_NE(Step(w), StepStatus::Failed) << w.failure;
    for (size_t i = 0; i < n; ++i) {
      bare[i]->PushReadings(w.robots[i]);
      ASSERT_TRUE(bare[i]->CallStep(&error)) << error;
    }
  }
  for (size_t i = 0; i < n; ++i) {
    lua_State* real = LuaStateOf(w.controllers[i].get());
    EXPECT_GT(Global(real, "messages"), 30) << "robot " << i << " heard too little to test the RAB replay";
    EXPECT_EQ(Global(bare[i]->State(), "messages"), Global(real, "messages")) << "robot " << i;
    EXPECT_EQ(Global(bare[i]->State(), "sum"), Global(real, "sum")) << "robot " << i;  // bit-identical
  }
}

TEST(BareFloor, ReplayComputesWhatTheRunComputed) { ExpectReplayComputesWhatTheRunComputed(BareAllocator::Stock); }

// The second floor, on the run's own allocator, must replay exactly the same work.
TEST(BareFloor, ReplayOnTheRunsAllocatorComputesWhatTheRunComputed) {
  ExpectReplayComputesWhatTheRunComputed(BareAllocator::Pool);
}

TEST(BareFloor, ActuatorsAreNoOpsInTheBareState) {
  TempDir d;
  d.Write("checksum.lua", kChecksum);
  Scene s = Load(d, Scenario());
  ASSERT_TRUE(s.ok()) << s.error;
  BareController b;
  std::string error;
  ASSERT_TRUE(b.Load(*s.model, s.model->robots[0], 0, 1, &error)) << error;
  lua_State* L = b.State();
  ASSERT_EQ(luaL_dostring(L,
                          "robot.wheels.set_velocity(1e300, 'not even a number'); "
                          "return robot.wheels.set_velocity == robot.range_and_bearing.set_data"),
            LUA_OK);
  EXPECT_TRUE(lua_toboolean(L, -1));  // one shared no-op, whatever the arguments
  ASSERT_EQ(luaL_dostring(L, "return type(robot.random.uniform())"), LUA_OK);
  EXPECT_STREQ(lua_tostring(L, -1), "number");  // robot.random kept
}

TEST(BareFloor, MeasureTimesEveryRobotStep) {
  TempDir d;
  d.Write("checksum.lua", kChecksum);
  Scene s = Load(d, Scenario());
  ASSERT_TRUE(s.ok()) << s.error;
  BareFloor f;
  std::string error;
  ASSERT_TRUE(MeasureBareFloor(*s.model, &f, &error)) << error;
  EXPECT_EQ(f.ticks, 30);
  EXPECT_EQ(f.robot_steps, 30 * 6);
  EXPECT_GT(f.step_seconds, 0);
  EXPECT_GT(f.step_cpu_seconds, 0);
  EXPECT_GT(f.pool_step_seconds, 0);  // both floors measured
  EXPECT_GT(f.pool_step_cpu_seconds, 0);
}

TEST(BareFloor, RobotsStoppedByAnErrorAreNotReplayed) {
  // As in a run: a controller that raised is never stepped again, so it has no floor either.
  TempDir d;
  d.Write("checksum.lua", "function step() if robot.id == 'fb0' then error('boom') end end");
  Scene s = Load(d, Scenario());
  ASSERT_TRUE(s.model) << s.error;
  BareFloor f;
  std::string error;
  ASSERT_TRUE(MeasureBareFloor(*s.model, &f, &error)) << error;
  EXPECT_EQ(f.robot_steps, 30 * 5);
}

}  // namespace
}  // namespace essaim
