// Foot-bot motion against what ARGoS 3 (dynamics2d, 10 sub-steps) measured on the same moves
// (tests/data/motion/README.md): the first tick's acceleration of 1.68 kg after a sub-step of
// lag, a stop that gives that lag back, sliding along a wall and off a static cylinder with
// Chipmunk's product of frictions. The first, third and fourth fail on main b6d1799 by far
// more than their tolerance (its numbers in the comments); the stop held there too and
// guards the sub-step shift's way back.
#include <gtest/gtest.h>

#include <cmath>

#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

/// Wheels at `speed` cm/s from the first tick; stopped by the step() of tick `stop`.
std::string DriveThenStop(double speed, int stop) {
  return "local t = 0\nfunction init() robot.wheels.set_velocity(" + std::to_string(speed) + ", " +
         std::to_string(speed) + ") end\nfunction step() t = t + 1 if t == " + std::to_string(stop) +
         " then robot.wheels.set_velocity(0, 0) end end\n";
}

Scene Drive(TempDir& d, const std::string& arena_extra, double x, double y, double yaw_deg, double speed, int stop) {
  d.Write("drive.lua", DriveThenStop(speed, stop));
  return Load(d, Experiment(FootBot("fb0", x, y, yaw_deg, "c") + arena_extra, WheelsController("c", "drive.lua")));
}

TEST(ArgosMotion, FirstTickAccelerates168KilogramsAfterOneSubStepOfLag) {
  TempDir d;
  Scene s = Drive(d, "", 0, 0, 0, 10, 1000);
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 1);
  EXPECT_NEAR(s.world->physics.RobotPose(0).x, 0.00889, 2e-5);  // ARGoS 8.89 mm (1.6 kg, Box2D's order: 9.94)
  RunTicks(*s.world, 1);
  EXPECT_NEAR(s.world->physics.RobotPose(0).x, 0.01889, 2e-5);  // then 10 mm a tick
}

TEST(ArgosMotion, StopGivesBackTheStartsLag) {
  TempDir d;
  Scene s = Drive(d, "", 0, 0, 0, 10, 30);  // 30 ticks at 10 cm/s, then braked
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 40);
  EXPECT_NEAR(s.world->physics.RobotPose(0).x, 0.3, 1e-6);  // ARGoS: 0.300000 m
}

TEST(ArgosMotion, SlidesAlongAWallAtArgossSpeed) {
  TempDir d;
  // 30 cm/s at 60° to a wall along x: 30° off its normal.
  Scene s = Drive(d, Box("w", 0, 0.5, 4, 0.1, 0.5), 0, 0, 60, 30, 1000);
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 30);
  const double before = s.world->physics.RobotPose(0).x;
  RunTicks(*s.world, 1);
  EXPECT_NEAR(s.world->physics.RobotPose(0).x - before, 0.0132, 2e-4);  // ARGoS 13.2 mm (sqrt friction: 8.1)
}

TEST(ArgosMotion, GlancingAStaticCylinderSlidesOff) {
  TempDir d;
  // Heading 6° off the line through the centres at contact: ARGoS slides off from 4°, Box2D's
  // sqrt friction only from 14.8° (the robot stuck at x = 0.317 for good).
  const double offset = (0.2 + footbot::kRadius) * std::sin(6 * kPi / 180);
  std::string cylinder = "<cylinder id=\"c\" radius=\"0.2\" height=\"0.3\" movable=\"false\"><body position=\"0.6," +
                         std::to_string(offset) + ",0\"/></cylinder>";
  Scene s = Drive(d, cylinder, 0, 0, 0, 20, 1000);
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 100);
  EXPECT_GT(s.world->physics.RobotPose(0).x, 0.6);  // round it and past its centre (1.13 m)
}

}  // namespace
}  // namespace essaim
