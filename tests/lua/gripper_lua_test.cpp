// Gripper and turret through unmodified-ARGoS-style Lua controllers: drive up to a
// cylinder with the gripper locked and push it, turn in place under it (ARGoS's spring holds a
// distance, not a bearing), unlock and turn back until the disc touches it, let go; grip
// sideways with the turret in position mode and swing the turret back without the load.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

constexpr double kR = footbot::kRadius;

const char* kController =
    "<lua_controller id=\"c\"><actuators><differential_steering implementation=\"default\"/>"
    "<footbot_gripper implementation=\"default\"/><footbot_turret implementation=\"default\"/></actuators>"
    "<sensors><differential_steering implementation=\"default\"/><positioning implementation=\"default\"/>"
    "<footbot_turret_encoder implementation=\"default\"/></sensors>"
    "<params script=\"ctrl.lua\"/></lua_controller>";

std::string Cylinder(double x, double y) {
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "<cylinder id=\"c0\" radius=\"0.05\" height=\"0.1\" movable=\"true\" mass=\"0.2\">"
                "<body position=\"%g,%g,0\" orientation=\"0,0,0\"/></cylinder>",
                x, y);
  return buf;
}

Vec2 InRobotFrame(const Pose2& pose, const Pose2& p) {
  Vec2 d(p.x - pose.x, p.y - pose.y);
  double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  return {c * d.x() + s * d.y(), -s * d.x() + c * d.y()};
}

TEST(GripperLua, DriveGripSpinRelease) {
  TempDir d;
  d.Write("ctrl.lua", R"(
local t = 0
function init()
  robot.gripper.lock_positive()
  robot.wheels.set_velocity(5, 5)
end
function step()
  t = t + 1
  if t == 60 then robot.wheels.set_velocity(-5, 5) end   -- spin in place, 0.714 rad/s
  if t == 104 then robot.wheels.set_velocity(0, 0) end   -- ~ half a turn later
  if t == 110 then robot.gripper.unlock() robot.wheels.set_velocity(5, -5) end  -- turn back
  if t == 156 then robot.wheels.set_velocity(-5, -5) end  -- turned a little past the start
end
function reset() end
function destroy() end
)");
  Scene s = Load(d, Experiment(FootBot("fb", 0, 0, 0, "c") + Cylinder(0.3, 0), kController, 200));
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  // Contact after (0.3 − 0.085 − 0.05 − 0.01) / 0.005 ≈ 31 ticks; carried from then on.
  RunTicks(w, 30);
  EXPECT_FALSE(w.physics.Gripped(0).Holding());
  RunTicks(w, 3);
  ASSERT_TRUE(w.physics.Gripped(0).Holding());
  RunTicks(w, 26);  // t = 59: still driving straight, cylinder pushed ahead and held
  Pose2 p = w.physics.RobotPose(0), c = w.physics.ObstaclePose(0);
  EXPECT_NEAR(p.x, 59 * 0.005, 0.01);
  Vec2 rel = InRobotFrame(p, c);
  EXPECT_NEAR(rel.x(), kR + 0.05, 0.012);
  EXPECT_NEAR(rel.y(), 0, 1e-3);
  Step(w);  // t = 60: the last tick driving straight (the turn of step 60 acts in tick 61)
  const Pose2 c0 = w.physics.ObstaclePose(0);
  for (int t = 61; t <= 103; ++t) {  // the robot turns under it: it stays where it is
    Step(w);
    c = w.physics.ObstaclePose(0);
    ASSERT_NEAR(c.x, c0.x, 0.005) << "t " << t;
    ASSERT_NEAR(c.y, c0.y, 0.005) << "t " << t;
  }
  RunTicks(w, 6);  // t = 109: stopped (the stop of step 104 acts in tick 105), still held
  EXPECT_TRUE(w.physics.Gripped(0).Holding());
  EXPECT_NEAR(WrapSigned(w.physics.RobotPose(0).yaw - kPi), 0, 0.1) << "half a turn";
  c = w.physics.ObstaclePose(0);
  p = w.physics.RobotPose(0);
  EXPECT_GT(c.x, p.x + kR) << "now behind the robot";
  RunTicks(w, 3);  // t = 112: unlocked, but the disc, facing away, touches nothing
  EXPECT_TRUE(w.physics.Gripped(0).Holding());
  // Turning back, the disc meets the cylinder as it passes it: released. (It was gripped at
  // the disc's first touch, so the spring holds it just within the disc's reach.)
  RunTicks(w, 44);  // t = 156
  EXPECT_FALSE(w.physics.Gripped(0).Holding());
  RunTicks(w, 2);
  Pose2 c2 = w.physics.ObstaclePose(0);
  RunTicks(w, 30);  // backing away for 3 s
  Pose2 c3 = w.physics.ObstaclePose(0);
  EXPECT_NEAR(c3.x, c2.x, 2e-3);
  EXPECT_NEAR(c3.y, c2.y, 2e-3);
  Pose2 p3 = w.physics.RobotPose(0);
  EXPECT_GT(std::hypot(p3.x - c3.x, p3.y - c3.y), kR + 0.05 + 0.1);
}

TEST(GripperLua, TurretGripsSidewaysAndSwingsBackWithoutTheLoad) {
  TempDir d;
  // The census pattern: set_position_control_mode() + set_rotation(a), lock, wait for the
  // encoder, swing back.
  d.Write("ctrl.lua", R"(
local phase = 0
function init()
  robot.turret.set_position_control_mode()
  robot.turret.set_rotation(math.pi / 2)
  robot.gripper.lock_positive()
end
function step()
  if phase == 0 and math.abs(robot.turret.rotation - math.pi / 2) < 0.01 then
    phase = 1
    robot.turret.set_rotation(0)
  end
  log(string.format("%d %.9f", phase, robot.turret.rotation))
end
)");
  const double side = kR + 0.05 + 0.002;
  std::vector<std::string> lines;
  SimOptions sim;
  sim.log_sink = [&](char, const std::string& line, const LogOrigin&) { lines.push_back(line); };
  Scene s = Load(d, Experiment(FootBot("fb", 0, 0, 0, "c") + Cylinder(0, side), kController, 600), {}, sim);
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  double turret_at_grip = 0;
  int grip_tick = 0;
  for (int t = 1; t <= 600 && !grip_tick; ++t) {
    Step(w);
    if (w.physics.Gripped(0).Holding()) {
      grip_tick = t;
      turret_at_grip = w.robots[0].turret_rotation;
    }
  }
  ASSERT_GT(grip_tick, 0);
  EXPECT_GT(turret_at_grip, 1.0) << "gripped only once the turret faced the cylinder";
  EXPECT_LT(turret_at_grip, kPi / 2 + 0.01);
  // From the grip on, the cylinder stays at the robot's side (the spring's end on the robot is
  // its centre) while the turret swings back to the front.
  const Pose2 c0 = w.physics.ObstaclePose(0);
  while (w.tick < 600) {
    Step(w);
    const Pose2 c = w.physics.ObstaclePose(0);
    ASSERT_NEAR(c.x, c0.x, 0.004) << "tick " << w.tick;
    ASSERT_NEAR(c.y, c0.y, 0.004) << "tick " << w.tick;
  }
  EXPECT_TRUE(w.physics.Gripped(0).Holding());
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines.back().substr(0, 1), "1") << "the controller saw the turret arrive";
  EXPECT_NEAR(w.robots[0].turret_rotation, 0, 0.01) << "and swung back";
  double last = std::strtod(lines.back().c_str() + 2, nullptr);
  EXPECT_NEAR(last, w.robots[0].turret_rotation, 1e-8) << "robot.turret.rotation is the encoder";
}

}  // namespace
}  // namespace essaim
