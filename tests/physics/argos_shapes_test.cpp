// The shapes as ARGoS's dynamics2d has them: the foot-bot's gripper disc (seen by other
// robots' rays, not by the robot's own, turning with the turret, colliding with nothing),
// static boxes without Box2D's skin, tiled walls without seams, the start yaw wrapped.
#include <gtest/gtest.h>

#include <cmath>

#include "devices/devices.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

constexpr double kR = footbot::kRadius;
constexpr double kRayZ = footbot::kProximityElevation;

Scene Still(const TempDir& d, const std::string& arena) {
  d.Write("still.lua", "function init() end\nfunction step() end\n");
  return Load(d, Experiment(arena, WheelsController("c", "still.lua")));
}

TEST(GripperDisc, OtherRobotsRaysMeetItTheRobotsOwnDoNot) {
  TempDir d;
  // Nose to nose, fronts 3 cm apart: robot 1's disc (radius 1 cm) sticks out 1 cm from its body.
  const double gap = 0.03;
  Scene s = Still(d, FootBot("a", 0, 0, 0, "c") + FootBot("b", 2 * kR + gap, 0, 180, "c"));
  ASSERT_TRUE(s.ok()) << s.error;
  const PhysicsWorld& p = s.world->physics;
  const RayHit hit = p.CastRay({kR, 0}, {kR + 0.1, 0}, kRayZ, 0);
  ASSERT_TRUE(hit.Hit());
  EXPECT_EQ(hit.kind, BodyKind::Gripper);
  EXPECT_EQ(hit.index, 1);
  EXPECT_NEAR(hit.distance, gap - kGripperRadius, 1e-6);
  // ARGoS's proximity value there: 0.0100527 / (0.02 + 0.000163144) = 0.4986.
  EXPECT_NEAR(ProximityValue(hit.distance), 0.4986, 1e-4);
  // Robot 1 looking out over its own disc sees robot 0's body, not its disc.
  const RayHit back = p.CastRay({2 * kR + gap - kR, 0}, {2 * kR + gap - kR - 0.1, 0}, kRayZ, 1);
  ASSERT_TRUE(back.Hit());
  EXPECT_EQ(back.kind, BodyKind::Gripper);  // robot 0's disc, 1 cm ahead of its body
  EXPECT_EQ(back.index, 0);
  // Above the body's height nothing is there.
  EXPECT_FALSE(p.CastRay({kR, 0}, {kR + 0.1, 0}, footbot::kHeight + 0.01, 0).Hit());
}

TEST(GripperDisc, TurnsWithTheTurret) {
  TempDir d;
  Scene s = Still(d, FootBot("a", 1, 2, 90, "c"));
  ASSERT_TRUE(s.ok()) << s.error;
  PhysicsWorld& p = s.world->physics;
  EXPECT_NEAR(p.GripperDiscPoint(0).x(), 1, 1e-6);
  EXPECT_NEAR(p.GripperDiscPoint(0).y(), 2 + kR, 1e-6);
  p.SetGripTurret(0, kPi / 2);  // turret to the robot's left: west
  EXPECT_NEAR(p.GripperDiscPoint(0).x(), 1 - kR, 1e-6);
  EXPECT_NEAR(p.GripperDiscPoint(0).y(), 2, 1e-6);
  const RayHit hit = p.CastRay({1 - 0.2, 2}, {1, 2}, kRayZ, -1);
  ASSERT_TRUE(hit.Hit());
  EXPECT_EQ(hit.kind, BodyKind::Gripper);
  EXPECT_NEAR(hit.distance, 0.2 - kR - kGripperRadius, 1e-6);
}

TEST(GripperDisc, CollidesWithNothingTheBodyTouchesTheWall) {
  TempDir d;
  d.Write("go.lua", "function init() robot.wheels.set_velocity(10, 10) end\nfunction step() end\n");
  // Head-on into a wall whose face is at x = 0.5: the disc would stop the body 1 cm short.
  const std::string arena = FootBot("fb0", 0, 0, 0, "c") + Box("wall", 0.55, 0, 0.1, 2, 0.5);
  Scene s = Load(d, Experiment(arena, WheelsController("c", "go.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 80);  // 8 s at 10 cm/s: 0.8 m wanted, 0.415 m to the face
  const double gap = 0.5 - (s.world->physics.RobotPose(0).x + kR);
  EXPECT_LT(gap, 0.003);
  EXPECT_GT(gap, -0.006);  // Box2D's slop, not a pass through
}

TEST(StaticBox, LeavesARobotBesideItWhereItIs) {
  TempDir d;
  // 2 mm from the face: inside Box2D's 1 cm polygon skin, which pushed it out to 5 mm.
  const double x = 0.3 - 0.002 - kR;
  Scene s = Still(d, FootBot("a", x, 0, 0, "c") + Box("b", 0.35, 0, 0.1, 0.3, 0.2));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 5);
  EXPECT_NEAR(s.world->physics.RobotPose(0).x, x, 1e-6);
  EXPECT_NEAR(s.world->physics.RobotPose(0).y, 0, 1e-6);
}

TEST(StaticBox, ATiledWallHasNoSeamsForRays) {
  TempDir d;
  // 4 m long: four pieces of 1 m whose seams lie at x = -1, 0, 1.
  Scene s = Still(d, FootBot("a", 0, -1, 0, "c") + Box("wall", 0, 1.05, 4, 0.1, 0.5));
  ASSERT_TRUE(s.ok()) << s.error;
  for (double x : {-1.0, 0.0, 1.0}) {
    for (double nudge : {-1e-7, 0.0, 1e-7}) {
      const RayHit hit = s.world->physics.CastRay({x + nudge, 0.9}, {x + nudge, 1.2}, kRayZ, -1);
      ASSERT_TRUE(hit.Hit()) << x + nudge;
      EXPECT_NEAR(hit.distance, 0.1, 1e-6) << x + nudge;
    }
  }
}

TEST(StartYaw, IsWrappedAsArgosQuaternionRoundTripDoes) {
  TempDir d;
  Scene s = Still(d, FootBot("a", 0, 0, 300, "c") + FootBot("b", 1, 0, -200, "c") + FootBot("c", 2, 0, 90, "c"));
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_NEAR(s.world->physics.RobotPose(0).yaw, DegToRad(-60), 1e-6);
  EXPECT_NEAR(s.world->physics.RobotPose(1).yaw, DegToRad(160), 1e-6);
  EXPECT_NEAR(s.world->physics.RobotPose(2).yaw, DegToRad(90), 1e-6);
}

}  // namespace
}  // namespace essaim
