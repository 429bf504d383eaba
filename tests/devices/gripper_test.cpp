// Foot-bot gripper: what it grips, that ARGoS's spring holds a distance (not a bearing) and
// tows, that the turret does not carry what it holds, that unlocking lets go at the disc's
// next contact. Commands are written straight into RobotState (a controller without
// script), as Lua would.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

constexpr double kR = footbot::kRadius;
constexpr double kCyl = 0.05;   // cylinder radius (m)
constexpr double kGap = 0.002;  // initial gap between robot and object (m), inside the 1 cm disc

const char* kGripController =
    "<lua_controller id=\"g\"><actuators><differential_steering implementation=\"default\"/>"
    "<footbot_gripper implementation=\"default\"/><footbot_turret implementation=\"default\"/></actuators>"
    "<sensors><footbot_turret_encoder implementation=\"default\"/></sensors><params script=\"" ESSAIM_SOURCE_DIR
    "/tests/support/idle.lua\"/></lua_controller>";

std::string Cylinder(const std::string& id, double x, double y, bool movable = true, double mass = 0.1) {
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "<cylinder id=\"%s\" radius=\"%g\" height=\"0.1\" movable=\"%s\" mass=\"%g\">"
                "<body position=\"%g,%g,0\" orientation=\"0,0,0\"/></cylinder>",
                id.c_str(), kCyl, movable ? "true" : "false", mass, x, y);
  return buf;
}

/// The robot-frame position of `p` for a robot at `pose`.
Vec2 InRobotFrame(const Pose2& pose, const Vec2& p) {
  Vec2 d = p - Vec2(pose.x, pose.y);
  double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  return {c * d.x() + s * d.y(), -s * d.x() + c * d.y()};
}

void Wheels(RobotState& r, double left_cm, double right_cm) {
  r.cmd.wheel_left = left_cm * 0.01;
  r.cmd.wheel_right = right_cm * 0.01;
  r.cmd.wheels_new = true;
}

Scene LoadScene(const TempDir& d, const std::string& arena, int ticks = 1000) {
  return Load(d, Experiment(arena, kGripController, ticks));
}

// ARGoS's spring holds one distance, from the robot's centre: turning in place, the robot
// turns under the object, which stays where it is; driving, it drags it at that distance.
TEST(Gripper, SpringHoldsTheDistanceNotTheBearing) {
  TempDir d;
  const double front = kR + kCyl + kGap;  // hand value: cylinder centre ahead of the robot
  Scene s = LoadScene(d, FootBot("fb", 0, 0, 0, "g") + Cylinder("c", front, 0));
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  RobotState& r = w.robots[0];
  Step(w);
  EXPECT_FALSE(w.physics.Gripped(0).Holding()) << "unlocked grippers grip nothing";
  r.cmd.gripper_aperture = kPi / 2;  // lock_positive
  Step(w);
  GripTarget g = w.physics.Gripped(0);
  ASSERT_EQ(g.kind, BodyKind::Obstacle);
  EXPECT_EQ(g.index, 0);
  EXPECT_DOUBLE_EQ(r.gripper_aperture, kPi / 2);

  // Spin in place: ω = (5 − (−5)) cm/s / 14 cm = 0.714 rad/s, half a turn in ~44 ticks.
  Wheels(r, -5, 5);
  int ticks = 0;
  while (w.physics.RobotPose(0).yaw < kPi && ticks < 100) {
    Step(w);
    ++ticks;
    Pose2 c = w.physics.ObstaclePose(0);
    ASSERT_NEAR(c.x, front, 0.002) << "tick " << ticks;
    ASSERT_NEAR(c.y, 0, 0.002) << "tick " << ticks;
  }
  EXPECT_NEAR(ticks, 44, 2);
  EXPECT_TRUE(w.physics.Gripped(0).Holding());
  // Now behind the robot; 2 s ahead at 5 cm/s drags it 10 cm, still at the spring's length.
  Wheels(r, 5, 5);
  RunTicks(w, 20);
  Pose2 p = w.physics.RobotPose(0), c = w.physics.ObstaclePose(0);
  EXPECT_NEAR(c.x, front - 0.1, 0.01);
  EXPECT_NEAR(std::hypot(c.x - p.x, c.y - p.y), front, 0.003);
  EXPECT_LT(InRobotFrame(p, {c.x, c.y}).x(), -kR) << "it trails behind";
}

// ARGoS lets go in its gripper-grippable contact callback: unlocked, the gripper releases at
// its disc's next contact with a grippable shape, not before.
TEST(Gripper, UnlockLetsGoWhenTheDiscTouchesAGrippableShape) {
  TempDir d;
  const double front = kR + kCyl + kGap;
  Scene s = LoadScene(d, FootBot("fb", 0, 0, 0, "g") + Cylinder("c", front, 0));
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  RobotState& r = w.robots[0];
  r.cmd.gripper_aperture = kPi / 2;
  Step(w);
  ASSERT_TRUE(w.physics.Gripped(0).Holding());
  // Half a turn: the disc now faces away from the cylinder behind. Unlocked, it still holds.
  Wheels(r, -5, 5);
  RunTicks(w, 44);
  Wheels(r, 0, 0);
  RunTicks(w, 2);
  r.cmd.gripper_aperture = 0;  // unlock
  RunTicks(w, 3);
  EXPECT_TRUE(w.physics.Gripped(0).Holding()) << "the disc touches nothing";
  // Turning back, the disc meets the cylinder: released.
  Wheels(r, 5, -5);
  int ticks = 0;
  while (w.physics.Gripped(0).Holding() && ticks < 60) {
    Step(w);
    ++ticks;
  }
  EXPECT_FALSE(w.physics.Gripped(0).Holding());
  EXPECT_GT(ticks, 30);
  // It stays put while the robot backs away.
  Wheels(r, 0, 0);
  RunTicks(w, 2);
  Pose2 before = w.physics.ObstaclePose(0);
  Wheels(r, -5, -5);
  RunTicks(w, 20);
  Pose2 after = w.physics.ObstaclePose(0);
  EXPECT_NEAR(after.x, before.x, 1e-3);
  EXPECT_NEAR(after.y, before.y, 1e-3);
  Pose2 away = w.physics.RobotPose(0);
  EXPECT_GT(std::hypot(away.x - after.x, away.y - after.y), front + 0.08) << "the robot left without it";
}

TEST(Gripper, LockedGripperGripsWhatItReachesLater) {
  TempDir d;
  // 5 cm beyond the disc: out of reach until the robot drives up to it.
  Scene s = LoadScene(d, FootBot("fb", 0, 0, 0, "g") + Cylinder("c", kR + kCyl + 0.05, 0));
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  RobotState& r = w.robots[0];
  r.cmd.gripper_aperture = -kPi / 2;  // lock_negative locks too
  RunTicks(w, 3);
  EXPECT_FALSE(w.physics.Gripped(0).Holding());
  Wheels(r, 5, 5);
  int ticks = 0;
  while (!w.physics.Gripped(0).Holding() && ticks < 30) {
    Step(w);
    ++ticks;
  }
  // Reach: the gap (5 cm) less the disc (1 cm) at 0.5 cm per tick ≈ 8 ticks (the grip
  // comes at the sub-step of contact).
  EXPECT_GE(ticks, 7);
  EXPECT_LE(ticks, 10);
  // Then it carries it: 1 s more at 5 cm/s moves the cylinder ~5 cm, still in front.
  double x0 = w.physics.ObstaclePose(0).x;
  RunTicks(w, 10);
  Pose2 c = w.physics.ObstaclePose(0);
  EXPECT_NEAR(c.x - x0, 0.05, 0.005);
  Vec2 rel = InRobotFrame(w.physics.RobotPose(0), {c.x, c.y});
  EXPECT_LT(rel.x(), kR + kCyl + 0.01);
  EXPECT_NEAR(rel.y(), 0, 1e-3);
}

TEST(Gripper, StaticAndOutOfReachShapesAreNotGripped) {
  TempDir d;
  std::string arena = FootBot("fb", 0, 0, 0, "g") + Cylinder("fixed", kR + kCyl + kGap, 0, false) +
                      Cylinder("side", 0, kR + kCyl + kGap);  // touching, but at the robot's left
  Scene s = LoadScene(d, arena);
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  w.robots[0].cmd.gripper_aperture = kPi / 2;
  RunTicks(w, 5);
  EXPECT_FALSE(w.physics.Gripped(0).Holding());
}

TEST(Gripper, GripperPointTurnsWithTheTurret) {
  TempDir d;
  // The cylinder at the robot's left is reachable once the turret faces left.
  Scene s = LoadScene(d, FootBot("fb", 0, 0, 0, "g") + Cylinder("side", 0, kR + kCyl + kGap));
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  RobotState& r = w.robots[0];
  Vec2 p = w.physics.GripperPoint(0, kPi / 2);
  EXPECT_NEAR(p.x(), 0, 1e-6);
  EXPECT_NEAR(p.y(), kR, 1e-6);
  r.turret_rotation = kPi / 2;  // as if the turret had got there
  w.physics.SetGripTurret(0, kPi / 2);
  r.cmd.gripper_aperture = kPi / 2;
  Step(w);
  ASSERT_TRUE(w.physics.Gripped(0).Holding());
  EXPECT_EQ(w.physics.Gripped(0).kind, BodyKind::Obstacle);
}

// The spring's end on the robot is its centre: the turret turns the disc, not the load.
TEST(Gripper, TurretDoesNotCarryTheHeldObject) {
  TempDir d;
  const double front = kR + kCyl + kGap;
  Scene s = LoadScene(d, FootBot("fb", 0, 0, 0, "g") + Cylinder("c", front, 0));
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  RobotState& r = w.robots[0];
  r.cmd.gripper_aperture = kPi / 2;
  Step(w);
  ASSERT_TRUE(w.physics.Gripped(0).Holding());
  r.cmd.turret_mode = TurretMode::Position;
  r.cmd.turret_rotation = kPi / 2;
  RunTicks(w, 300);  // the PD converges within ~0.1% by then
  EXPECT_NEAR(r.turret_rotation, kPi / 2, 2e-3);
  Pose2 c = w.physics.ObstaclePose(0);
  EXPECT_NEAR(c.x, front, 0.002);
  EXPECT_NEAR(c.y, 0, 0.002);
  EXPECT_TRUE(w.physics.Gripped(0).Holding());
}

TEST(Gripper, TowsAnotherRobot) {
  TempDir d;
  // The towed robot brakes (zero wheels) with a weak servo, 2 N: the tower's 15 N wins.
  // (Two full-strength brakes, 15 N against 15 N, stall — as in ARGoS.)
  const double sep = 2 * kR + kGap;
  std::string towed = "<foot-bot id=\"towed\"><body position=\"" + std::to_string(sep) +
                      ",0,0\" orientation=\"0,0,0\"/>"
                      "<controller config=\"g\"/><dynamics2d><differential_steering max_force=\"2\" "
                      "max_torque=\"2\"/></dynamics2d></foot-bot>";
  Scene s = LoadScene(d, FootBot("tower", 0, 0, 0, "g") + towed);
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  RobotState& r = w.robots[0];
  r.cmd.gripper_aperture = kPi / 2;
  Step(w);
  GripTarget g = w.physics.Gripped(0);
  ASSERT_EQ(g.kind, BodyKind::Robot);
  EXPECT_EQ(g.index, 1);
  EXPECT_FALSE(w.physics.Gripped(1).Holding());
  // Back up at 5 cm/s for 5 s: both move 25 cm, keeping their separation.
  Wheels(r, -5, -5);
  RunTicks(w, 50);
  Pose2 a = w.physics.RobotPose(0), b = w.physics.RobotPose(1);
  EXPECT_NEAR(a.x, -0.25, 0.01);
  EXPECT_NEAR(b.x, sep - 0.25, 0.01);
  EXPECT_NEAR(b.x - a.x, sep, 0.003);
  EXPECT_NEAR(b.y, 0, 1e-3);
  EXPECT_NEAR(b.yaw, 0, 0.01);
  // Unlock and keep backing: the towed robot stays behind.
  r.cmd.gripper_aperture = 0;
  RunTicks(w, 20);
  Pose2 b2 = w.physics.RobotPose(1);
  EXPECT_NEAR(b2.x, b.x, 0.005);
  EXPECT_LT(w.physics.RobotPose(0).x, a.x - 0.08);
}

TEST(Gripper, AWeakSpringCannotMoveABrakedLoad) {
  TempDir d;
  // gripping_rigidity 1 N/m: stretched 25 cm it pulls 0.25 N, against a 2 N brake.
  const double sep = 2 * kR + kGap;
  std::string towed = "<foot-bot id=\"towed\"><body position=\"" + std::to_string(sep) +
                      ",0,0\" orientation=\"0,0,0\"/>"
                      "<controller config=\"g\"/><dynamics2d><differential_steering max_force=\"2\" "
                      "max_torque=\"2\"/></dynamics2d></foot-bot>";
  std::string xml = Experiment(FootBot("tower", 0, 0, 0, "g") + towed, kGripController, 1000);
  xml.insert(xml.find("iterations=\"10\""), "gripping_rigidity=\"1\" ");
  Scene s = Load(d, xml);
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  w.robots[0].cmd.gripper_aperture = kPi / 2;
  Step(w);
  ASSERT_TRUE(w.physics.Gripped(0).Holding());
  Wheels(w.robots[0], -5, -5);
  RunTicks(w, 50);
  EXPECT_NEAR(w.physics.RobotPose(0).x, -0.25, 0.02);
  EXPECT_NEAR(w.physics.RobotPose(1).x, sep, 0.002);
}

TEST(Gripper, TeleportingARobotCarriesWhatItHolds) {
  TempDir d;
  const double front = kR + kCyl + kGap;
  Scene s = LoadScene(d, FootBot("fb", 0, 0, 0, "g") + Cylinder("c", front, 0));
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  w.robots[0].cmd.gripper_aperture = kPi / 2;
  Step(w);
  ASSERT_TRUE(w.physics.Gripped(0).Holding());
  w.physics.SetRobotPose(0, {2, 1, kPi / 2});  // loop functions move the robot
  Pose2 c = w.physics.ObstaclePose(0);
  EXPECT_NEAR(c.x, 2, 1e-4);
  EXPECT_NEAR(c.y, 1 + front, 1e-4);
  RunTicks(w, 5);
  c = w.physics.ObstaclePose(0);
  EXPECT_NEAR(c.x, 2, 1e-3);
  EXPECT_NEAR(c.y, 1 + front, 1e-3);
}

TEST(Gripper, RigidityIsReadFromDynamics2d) {
  TempDir d;
  std::string xml = Experiment(FootBot("fb", 0, 0, 0, "g"), kGripController);
  size_t p = xml.find("iterations=\"10\"");
  xml.insert(p, "gripping_rigidity=\"500\" ");
  Scene s = Load(d, xml);
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_DOUBLE_EQ(s.model->physics.gripping_rigidity, 500);
  TempDir d2;
  Scene def = Load(d2, Experiment(FootBot("fb", 0, 0, 0, "g"), kGripController));
  ASSERT_TRUE(def.ok()) << def.error;
  EXPECT_DOUBLE_EQ(def.model->physics.gripping_rigidity, 10000);
}

}  // namespace
}  // namespace essaim
