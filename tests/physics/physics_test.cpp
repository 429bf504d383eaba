// Foot-bot motion against closed forms: v·t, (vr−vl)/axis, walls, pushing.
#include <gtest/gtest.h>

#include <cmath>

#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

std::string Drive(double l, double r) {
  return "function init() robot.wheels.set_velocity(" + std::to_string(l) + ", " + std::to_string(r) +
         ") end\nfunction step() end\n";
}

class Physics : public ::testing::TestWithParam<int> {};  // sub-steps per tick

std::string WithIterations(std::string xml, int it) {
  size_t p = xml.find("iterations=\"10\"");
  xml.replace(p, 15, "iterations=\"" + std::to_string(it) + "\"");
  return xml;
}

TEST_P(Physics, StraightDriveCoversVT) {
  TempDir d;
  d.Write("go.lua", Drive(10, 10));  // 10 cm/s
  Scene s =
      Load(d, WithIterations(Experiment(FootBot("fb0", -2, 0, 0, "c"), WheelsController("c", "go.lua")), GetParam()));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 100);  // 10 s
  Pose2 p = s.world->physics.RobotPose(0);
  // 1 m, less one sub-step's travel (ARGoS's engine moves bodies before it solves: the wheels
  // take effect one sub-step late) and ~0.1 mm of acceleration (15 N on 1.68 kg).
  EXPECT_NEAR(p.x, -1.0 - 0.1 * (0.1 / GetParam()), 5e-4);
  EXPECT_NEAR(p.y, 0.0, 1e-4);
  EXPECT_NEAR(p.yaw, 0.0, 1e-4);
}

TEST_P(Physics, SpinInPlaceTurnsAtDeltaVOverAxis) {
  TempDir d;
  d.Write("spin.lua", Drive(-5, 5));  // ω = 0.1 / 0.14 rad/s
  Scene s =
      Load(d, WithIterations(Experiment(FootBot("fb0", 0, 0, 0, "c"), WheelsController("c", "spin.lua")), GetParam()));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 100);
  Pose2 p = s.world->physics.RobotPose(0);
  double expected = 0.1 / 0.14 * 10;  // unwrapped: 7.14 rad
  EXPECT_NEAR(p.yaw, expected, 0.02 * expected);
  EXPECT_NEAR(p.x, 0, 1e-3);
  EXPECT_NEAR(p.y, 0, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(SubSteps, Physics, ::testing::Values(1, 2, 10));

TEST(PhysicsContacts, RobotDrivenIntoAWallStopsAtTheWall) {
  TempDir d;
  d.Write("go.lua", Drive(30, 30));
  std::string arena = FootBot("fb0", 0, 0, 0, "c") +
                      "<box id=\"wall\" size=\"0.1,4,0.5\" movable=\"false\"><body position=\"1.05,0,0\"/></box>";
  Scene s = Load(d, Experiment(arena, WheelsController("c", "go.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 100);  // would be 3 m without the wall
  Pose2 p = s.world->physics.RobotPose(0);
  double face = 1.0 - footbot::kRadius;  // wall face at x = 1.0
  EXPECT_LE(p.x, face + 0.01);
  EXPECT_GE(p.x, face - 0.02);
}

TEST(PhysicsContacts, HeadOnRobotsPushEachOtherToAStandstill) {
  TempDir d;
  d.Write("go.lua", Drive(20, 20));
  std::string arena = FootBot("a", -0.5, 0, 0, "c") + FootBot("b", 0.5, 0, 180, "c");
  Scene s = Load(d, Experiment(arena, WheelsController("c", "go.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 100);
  Pose2 a = s.world->physics.RobotPose(0), b = s.world->physics.RobotPose(1);
  // Equal force caps: they meet in the middle and stay there, never through each other.
  EXPECT_NEAR(a.x + b.x, 0, 0.01);
  EXPECT_GE(b.x - a.x, 2 * footbot::kRadius - 0.01);
  EXPECT_LE(b.x - a.x, 2 * footbot::kRadius + 0.02);
}

TEST(PhysicsContacts, PushingABrakedRobotIsLimitedByTheForceCaps) {
  TempDir d;
  d.Write("go.lua", Drive(20, 20));
  d.Write("stay.lua", "function step() end");
  std::string ctrls = WheelsController("go", "go.lua") + WheelsController("stay", "stay.lua");
  auto run = [&](const std::string& brake_force) {
    std::string braked =
        "<foot-bot id=\"b\"><body position=\"-0.3,0,0\"/><controller config=\"stay\"/>"
        "<dynamics2d><differential_steering max_force=\"" +
        brake_force + "\"/></dynamics2d></foot-bot>";
    Scene s = Load(d, Experiment(FootBot("a", -0.5, 0, 0, "go") + braked, ctrls));
    EXPECT_TRUE(s.ok()) << s.error;
    RunTicks(*s.world, 50);  // 5 s: 1 m if nothing were in the way
    Pose2 a = s.world->physics.RobotPose(0), b = s.world->physics.RobotPose(1);
    EXPECT_GE(b.x - a.x, 2 * footbot::kRadius - 0.01);  // never through each other
    return b.x + 0.3;                                   // how far the braked robot was pushed
  };
  // A brake four times stronger than the pusher's drive holds: it barely moves.
  EXPECT_LT(run("60"), 0.02);
  // Equal caps: Box2D's sequential solver does not balance two saturated servos exactly,
  // so the pair creeps, but well below the free speed.
  double pushed = run("15");
  EXPECT_GT(pushed, 0.0);
  EXPECT_LT(pushed, 0.7);
}

TEST(PhysicsContacts, RobotPushesAMovableCylinder) {
  TempDir d;
  d.Write("go.lua", Drive(10, 10));
  std::string arena = FootBot("a", 0, 0, 0, "c") +
                      "<cylinder id=\"cyl\" radius=\"0.1\" height=\"0.2\" movable=\"true\" mass=\"0.1\"><body "
                      "position=\"0.3,0,0\"/></cylinder>";
  Scene s = Load(d, Experiment(arena, WheelsController("c", "go.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 100);
  Pose2 c = s.world->physics.ObstaclePose(0);
  EXPECT_GT(c.x, 0.8);  // pushed about 0.8 m along
}

TEST(PhysicsQueries, RayHitsTheClosestShapeTallEnough) {
  TempDir d;
  d.Write("s.lua", "function step() end");
  std::string arena = FootBot("a", 0, 0, 0, "c") +
                      "<box id=\"low\" size=\"0.1,1,0.05\" movable=\"false\"><body position=\"0.5,0,0\"/></box>"
                      "<box id=\"high\" size=\"0.1,1,0.5\" movable=\"false\"><body position=\"1.0,0,0\"/></box>";
  Scene s = Load(d, Experiment(arena, WheelsController("c", "s.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  const PhysicsWorld& ph = s.world->physics;
  RayHit h = ph.CastRay({0, 0}, {2, 0}, 0.1, 0);  // robot 0 excluded; passes over the low box
  ASSERT_TRUE(h.Hit());
  EXPECT_EQ(h.kind, BodyKind::Obstacle);
  EXPECT_EQ(h.index, 1);
  EXPECT_NEAR(h.distance, 0.95, 1e-5);
  RayHit low = ph.CastRay({0, 0}, {2, 0}, 0.02, 0);
  EXPECT_EQ(low.index, 0);
  EXPECT_NEAR(low.distance, 0.45, 1e-5);
  RayHit self = ph.CastRay({-1, 0}, {0, 0}, 0.1, -1);  // not excluded: hits the robot's body
  EXPECT_EQ(self.kind, BodyKind::Robot);
  EXPECT_NEAR(self.distance, 1 - footbot::kRadius, 1e-5);
}

}  // namespace
}  // namespace essaim
