// Foot-bot turret and encoder: ARGoS's PD in position mode against
// hand-computed ticks, speed and passive modes, the encoder as Lua reads it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

const char* kTurretController =
    "<lua_controller id=\"t\"><actuators><footbot_turret implementation=\"default\"/></actuators>"
    "<sensors><footbot_turret_encoder implementation=\"default\"/></sensors><params %s/></lua_controller>";

std::string Controller(const std::string& script = "") {
  std::string params =
      "script=\"" + (script.empty() ? std::string(ESSAIM_SOURCE_DIR "/tests/support/idle.lua") : script) + "\"";
  char buf[512];
  std::snprintf(buf, sizeof buf, kTurretController, params.c_str());
  return buf;
}

/// Runs `script` on one foot-bot for `ticks` ticks; returns the numbers it log()ged.
std::vector<double> LoggedNumbers(const std::string& script, int ticks, std::vector<std::string>* errors = nullptr) {
  TempDir d;
  d.Write("turret.lua", script);
  std::vector<double> out;
  SimOptions sim;
  sim.log_sink = [&](char stream, const std::string& line, const LogOrigin&) {
    if (stream == 'O') out.push_back(std::strtod(line.c_str(), nullptr));
  };
  Scene s = Load(d, Experiment(FootBot("fb", 0, 0, 0, "t"), Controller("turret.lua"), ticks), {}, sim);
  EXPECT_TRUE(s.ok()) << s.error;
  if (!s.ok()) return out;
  RunTicks(*s.world, ticks);
  if (errors)
    for (const ControllerError& e : s.world->controller_errors) errors->push_back(e.message);
  return out;
}

TEST(Turret, PositionModeFollowsArgosPdTickByTick) {
  // init: position mode, target 1 rad. Act of tick k, then step k logs the encoder.
  std::vector<double> rot = LoggedNumbers(
      "function init() robot.turret.set_position_control_mode() robot.turret.set_rotation(1) end\n"
      "function step() log(string.format('%.12f', robot.turret.rotation)) end\n",
      300);
  ASSERT_EQ(rot.size(), 300u);
  // By hand, dt = 0.1 s, w = 0.4 e + 0.2 (e - e_prev) / dt, e_prev = 0 at start:
  //   tick 1: e = 1      w = 0.4 + 2.0           = 2.4      -> 0.24
  //   tick 2: e = 0.76   w = 0.304 - 0.48        = -0.176   -> 0.2224
  //   tick 3: e = 0.7776 w = 0.31104 + 0.0352    = 0.34624  -> 0.257024
  EXPECT_NEAR(rot[0], 0.24, 1e-9);
  EXPECT_NEAR(rot[1], 0.2224, 1e-9);
  EXPECT_NEAR(rot[2], 0.257024, 1e-9);
  // The same recurrence on, and convergence: error × ~0.967 per tick (roots of
  // r² − 0.76 r − 0.2), so after 300 ticks it is below 1e-4.
  double a = 0, prev = 0;
  for (int k = 0; k < 300; ++k) {
    double e = 1 - a;
    a += (0.4 * e + 0.2 * (e - prev) / 0.1) * 0.1;
    prev = e;
    ASSERT_NEAR(rot[k], a, 1e-9) << "tick " << k + 1;
  }
  EXPECT_NEAR(rot[299], 1.0, 1e-4);
  EXPECT_NEAR(rot[99], 1.0, 0.05);  // 10 s: within 5 %
}

TEST(Turret, SpeedModeTurnsAtXPiOver30AndWraps) {
  std::vector<double> rot = LoggedNumbers(
      "function init() robot.turret.set_speed_control_mode() robot.turret.set_rotation_speed(10) end\n"
      "function step() log(string.format('%.12f', robot.turret.rotation)) end\n",
      40);
  ASSERT_EQ(rot.size(), 40u);
  const double w = 10 * kPi / 30;  // rad/s
  for (int k = 0; k < 40; ++k) EXPECT_NEAR(WrapSigned(rot[k] - w * 0.1 * (k + 1)), 0, 1e-9) << "tick " << k + 1;
  // 4 s at 1.047 rad/s = 4.19 rad: past pi, so the reading has wrapped to negative.
  EXPECT_LT(rot[39], 0);
}

TEST(Turret, OffByDefaultAndPassiveKeepsTheAngle) {
  // set_rotation alone does nothing: the actuator starts off (ARGoS).
  std::vector<double> rot = LoggedNumbers(
      "function init() robot.turret.set_rotation(1) end\n"
      "function step() log(robot.turret.rotation) end\n",
      5);
  ASSERT_EQ(rot.size(), 5u);
  for (double r : rot) EXPECT_EQ(r, 0);
  // Speed for 5 ticks, then passive: the angle stays where it was.
  rot = LoggedNumbers(
      "n = 0\n"
      "function init() robot.turret.set_speed_control_mode() robot.turret.set_rotation_speed(-30) end\n"
      "function step() n = n + 1 if n == 5 then robot.turret.set_passive_mode() end\n"
      "  log(string.format('%.12f', robot.turret.rotation)) end\n",
      10);
  ASSERT_EQ(rot.size(), 10u);
  EXPECT_NEAR(rot[4], -kPi * 0.5, 1e-9);  // -30·pi/30 rad/s for 0.5 s
  for (int k = 5; k < 10; ++k) EXPECT_NEAR(rot[k], rot[4], 1e-12) << "tick " << k + 1;
}

TEST(Turret, PositionModeTakesTheShortWayRound) {
  TempDir d;
  Scene s = Load(d, Experiment(FootBot("fb", 0, 0, 0, "t"), Controller()));
  ASSERT_TRUE(s.ok()) << s.error;
  RobotState& r = s.world->robots[0];
  r.turret_rotation = 2.5;
  r.cmd.turret_mode = TurretMode::Position;
  r.cmd.turret_rotation = -2.5;  // 1.28 rad ahead through pi, 5 rad back the long way
  Step(*s.world);
  EXPECT_GT(r.turret_rotation, 2.5 + 0.2) << "first tick moves forward by 0.24·1.28";
  RunTicks(*s.world, 300);
  EXPECT_NEAR(r.turret_rotation, -2.5, 1e-3);
  EXPECT_NEAR(r.rd.turret_rotation, r.turret_rotation, 1e-12) << "the encoder reads the turret";
}

TEST(Turret, ArgumentChecks) {
  std::vector<std::string> errors;
  LoggedNumbers("function init() end\nfunction step() robot.turret:set_rotation(1) end\n", 1, &errors);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("set_rotation"), std::string::npos) << errors[0];
  errors.clear();
  LoggedNumbers("function init() end\nfunction step() robot.turret.set_rotation_speed() end\n", 1, &errors);
  ASSERT_EQ(errors.size(), 1u);
  errors.clear();
  LoggedNumbers("function init() end\nfunction step() robot.turret.set_rotation('x') end\n", 1, &errors);
  ASSERT_EQ(errors.size(), 1u);
}

TEST(Turret, EncoderIsZeroInInitAndDevicesAreListed) {
  std::vector<double> rot = LoggedNumbers("function init() log(robot.turret.rotation) end\nfunction step() end\n", 1);
  ASSERT_EQ(rot.size(), 1u);
  EXPECT_EQ(rot[0], 0);
  EXPECT_TRUE(GetDeviceRow(DeviceType::TurretActuator).supported);
  EXPECT_TRUE(GetDeviceRow(DeviceType::TurretEncoderSensor).supported);
  EXPECT_TRUE(GetDeviceRow(DeviceType::GripperActuator).supported);
}

}  // namespace
}  // namespace essaim
