// Battery: discharge per model against hand values — time: delta per tick;
// motion: pos_delta per metre moved and orient_delta per radian turned, on a robot driven
// straight and one spinning; time_motion: both — available_charge and time_left, and no
// <battery>, no discharge.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

const char* kBatteryController =
    "<lua_controller id=\"b\"><actuators><differential_steering implementation=\"default\"/></actuators>"
    "<sensors><battery implementation=\"default\"/></sensors><params script=\"" ESSAIM_SOURCE_DIR
    "/tests/support/idle.lua\"/></lua_controller>";
const char* kNoSensorController =
    "<lua_controller id=\"n\"><actuators><differential_steering implementation=\"default\"/></actuators>"
    "<sensors/><params script=\"" ESSAIM_SOURCE_DIR "/tests/support/idle.lua\"/></lua_controller>";

std::string Bot(const std::string& battery, double yaw_deg = 0, const std::string& ctrl = "b") {
  return "<foot-bot id=\"fb\"><body position=\"0,0,0\" orientation=\"" + std::to_string(yaw_deg) +
         ",0,0\"/><controller config=\"" + ctrl + "\"/>" + battery + "</foot-bot>";
}

Scene LoadBattery(const TempDir& d, const std::string& battery, double yaw_deg = 0) {
  return Load(d, Experiment(Bot(battery, yaw_deg), std::string(kBatteryController) + kNoSensorController, 1000));
}

void Wheels(RobotState& r, double left_cm, double right_cm) {
  r.cmd.wheel_left = left_cm * 0.01;
  r.cmd.wheel_right = right_cm * 0.01;
  r.cmd.wheels_new = true;
}

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(Battery, TimeModelSubtractsDeltaEveryTick) {
  TempDir d;
  Scene s = LoadBattery(d, "<battery discharge_model=\"time\" delta=\"0.001\"/>");
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  const Readings& rd = w.robots[0].rd;
  EXPECT_EQ(rd.battery_charge, 1.0) << "initial reading";
  EXPECT_EQ(rd.battery_time_left, kInf);
  Step(w);
  EXPECT_NEAR(rd.battery_charge, 0.999, 1e-12);
  // time_left = old · dt / (old − new) = 1 · 0.1 / 0.001
  EXPECT_NEAR(rd.battery_time_left, 100.0, 1e-6);
  RunTicks(w, 9);
  EXPECT_NEAR(rd.battery_charge, 0.99, 1e-12);
  EXPECT_NEAR(rd.battery_time_left, 0.991 * 0.1 / 0.001, 1e-6);  // old reading 0.991
}

TEST(Battery, FullChargeScalesTheReadingAndEmptyReadsZero) {
  TempDir d;
  Scene s = LoadBattery(d, "<battery discharge_model=\"time\" delta=\"0.1\" start_charge=\"1\" full_charge=\"2\"/>");
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  const Readings& rd = w.robots[0].rd;
  EXPECT_EQ(rd.battery_charge, 0.5);
  Step(w);
  EXPECT_NEAR(rd.battery_charge, 0.45, 1e-12);                // (1 − 0.1) / 2
  EXPECT_NEAR(rd.battery_time_left, 0.5 * 0.1 / 0.05, 1e-9);  // 1 s
  RunTicks(w, 12);                                            // empty after 10 ticks; never below 0
  EXPECT_EQ(w.robots[0].battery.charge, 0);
  EXPECT_EQ(rd.battery_charge, 0);
  EXPECT_EQ(rd.battery_time_left, 0);
}

TEST(Battery, TinyChangesLeaveTimeLeftInfinite) {
  TempDir d;
  Scene s = LoadBattery(d, "<battery discharge_model=\"time\" delta=\"1e-7\"/>");  // below 1e-6 per tick
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 3);
  EXPECT_NEAR(s.world->robots[0].rd.battery_charge, 1 - 3e-7, 1e-15);
  EXPECT_EQ(s.world->robots[0].rd.battery_time_left, kInf);
}

TEST(Battery, DefaultTimeModel) {
  TempDir d;
  Scene s = LoadBattery(d, "<battery/>");  // discharge_model defaults to time, delta to 1e-5
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 100);
  EXPECT_NEAR(s.world->robots[0].rd.battery_charge, 1 - 100 * 1e-5, 1e-12);
  EXPECT_NEAR(s.world->robots[0].rd.battery_time_left, (1 - 99e-5) * 0.1 / 1e-5, 1e-3);
}

TEST(Battery, MotionModelChargesPerMetreDrivenStraight) {
  TempDir d;
  Scene s = LoadBattery(d, "<battery discharge_model=\"motion\" pos_delta=\"0.01\" orient_delta=\"0.5\"/>");
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  Step(w);
  EXPECT_EQ(w.robots[0].rd.battery_charge, 1.0) << "standing still costs nothing";
  EXPECT_EQ(w.robots[0].rd.battery_time_left, kInf);
  Wheels(w.robots[0], 10, 10);
  RunTicks(w, 100);  // 10 s at 10 cm/s: 1 m (less a few mm of acceleration)
  double moved = w.physics.RobotPose(0).x;
  EXPECT_NEAR(moved, 1.0, 0.005);
  EXPECT_NEAR(w.robots[0].rd.battery_charge, 1 - 0.01 * moved, 1e-6);
  EXPECT_NEAR(w.robots[0].rd.battery_charge, 0.99, 1e-4);
  // Per tick: 1 cm costs 1e-4, above the 1e-6 threshold: time_left = old · 0.1 / 1e-4.
  double old = 1 - 0.01 * (moved - 0.01);
  EXPECT_NEAR(w.robots[0].rd.battery_time_left, old * 0.1 / 1e-4, 5);
}

TEST(Battery, MotionModelChargesPerRadianSpun) {
  TempDir d;
  Scene s = LoadBattery(d, "<battery discharge_model=\"motion\" pos_delta=\"5\" orient_delta=\"0.01\"/>");
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  Wheels(w.robots[0], -5, 5);  // ω = 0.1 / 0.14 = 0.714 rad/s in place
  RunTicks(w, 100);
  double turned = w.physics.RobotPose(0).yaw;  // unwrapped: 7.14 rad, more than a full turn
  EXPECT_NEAR(turned, 0.1 / 0.14 * 10, 0.02);
  Vec2 drift(w.physics.RobotPose(0).x, w.physics.RobotPose(0).y);
  EXPECT_LT(drift.norm(), 1e-3);
  // Every radian counts, also past pi: 1 − 0.01 · 7.14 (plus a sub-mm drift at 5 per m).
  EXPECT_NEAR(w.robots[0].rd.battery_charge, 1 - 0.01 * turned, 5 * drift.norm() + 1e-6);
  EXPECT_NEAR(w.robots[0].rd.battery_charge, 1 - 0.01 * 0.1 / 0.14 * 10, 5e-3);
}

TEST(Battery, InitialHeadingIsNotCharged) {
  // ARGoS charges a robot placed at yaw θ for θ on its first tick (q_old starts at the
  // identity); essaim does not (docs/compatibility.md).
  TempDir d;
  Scene s = LoadBattery(d, "<battery discharge_model=\"motion\" orient_delta=\"0.1\"/>", 90);
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 5);
  EXPECT_EQ(s.world->robots[0].rd.battery_charge, 1.0);
}

TEST(Battery, TimeMotionModelAddsBoth) {
  TempDir d;
  Scene s = LoadBattery(d,
                        "<battery discharge_model=\"time_motion\" time_factor=\"0.001\" pos_factor=\"0.02\" "
                        "orient_factor=\"0.5\"/>");
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  Wheels(w.robots[0], 10, 10);
  RunTicks(w, 50);  // 5 s: 50 ticks of time, ~0.5 m
  double moved = w.physics.RobotPose(0).x;
  EXPECT_NEAR(moved, 0.5, 0.005);
  EXPECT_NEAR(w.robots[0].rd.battery_charge, 1 - 50 * 0.001 - 0.02 * moved, 1e-6);
  EXPECT_NEAR(w.robots[0].rd.battery_charge, 1 - 0.05 - 0.01, 2e-4);
}

TEST(Battery, WithoutBatteryElementNeverDepletes) {
  TempDir d;
  Scene s = LoadBattery(d, "");
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  Wheels(w.robots[0], 10, -10);
  RunTicks(w, 200);
  EXPECT_EQ(w.robots[0].rd.battery_charge, 1.0);
  EXPECT_EQ(w.robots[0].rd.battery_time_left, kInf);
  EXPECT_EQ(w.robots[0].battery.charge, 1.0);
}

TEST(Battery, DischargesWithoutTheSensorToo) {
  // essaim deviation: the <battery> element alone drives discharge (ARGoS needs the sensor).
  TempDir d;
  Scene s = Load(d, Experiment(Bot("<battery delta=\"0.01\"/>", 0, "n"),
                               std::string(kBatteryController) + kNoSensorController, 1000));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 10);
  EXPECT_NEAR(s.world->robots[0].battery.charge, 0.9, 1e-12);
}

TEST(Battery, LuaSeesInitialValuesInInitThenTheDischarge) {
  TempDir d;
  d.Write("b.lua",
          "function init() log(robot.battery.available_charge, ' ', robot.battery.time_left == math.huge) end\n"
          "function step() log(string.format('%.12f %.9f', robot.battery.available_charge, robot.battery.time_left)) "
          "end\n");
  std::vector<std::string> lines;
  SimOptions sim;
  sim.log_sink = [&](char, const std::string& line, const LogOrigin&) { lines.push_back(line); };
  std::string ctrl =
      "<lua_controller id=\"b\"><actuators/><sensors><battery implementation=\"default\"/></sensors>"
      "<params script=\"b.lua\"/></lua_controller>";
  Scene s = Load(d, Experiment(Bot("<battery delta=\"0.002\" start_charge=\"0.8\"/>"), ctrl, 10), {}, sim);
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 2);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "0.8 1");                        // ARGoS's log(): no separator, true as 1
  EXPECT_EQ(lines[1], "0.798000000000 40.000000000");  // 0.8 · 0.1 / 0.002
  EXPECT_EQ(lines[2], "0.796000000000 39.900000000");  // 0.798 · 0.1 / 0.002
}

}  // namespace
}  // namespace essaim
