// Several physics regions stepping: robots migrate across a boundary, bodies on either side
// of it collide (through each world's ghosts of its neighbours), and the results are
// bit-identical whatever the thread count.
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

// Two engines splitting the 10 × 10 m arena at x = 0 (ARGoS's <boundaries>).
const char* kTwoEngines =
    "<dynamics2d id=\"west\" iterations=\"10\"><boundaries><top height=\"1\"/><bottom height=\"0\"/><sides>"
    "<vertex point=\"-5,-5\"/><vertex point=\"0,-5\"/><vertex point=\"0,5\"/><vertex point=\"-5,5\"/>"
    "</sides></boundaries></dynamics2d>"
    "<dynamics2d id=\"east\" iterations=\"10\"><boundaries><top height=\"1\"/><bottom height=\"0\"/><sides>"
    "<vertex point=\"0,-5\"/><vertex point=\"5,-5\"/><vertex point=\"5,5\"/><vertex point=\"0,5\"/>"
    "</sides></boundaries></dynamics2d>";

std::string WithEngines(std::string xml, const std::string& engines) {
  const std::string one = "<dynamics2d id=\"dyn2d\" iterations=\"10\"/>";
  xml.replace(xml.find(one), one.size(), engines);
  return xml;
}

TEST(RegionStepping, RobotDrivingAcrossTheBoundaryMigratesAndKeepsGoing) {
  TempDir d;
  d.Write("go.lua", Drive(10, 10));  // 10 cm/s east
  const std::string xml = Experiment(FootBot("fb0", -0.5, 0, 0, "c"), WheelsController("c", "go.lua"), 100);
  Scene one = Load(d, xml);
  Scene two = Load(d, WithEngines(xml, kTwoEngines));
  ASSERT_TRUE(one.ok() && two.ok()) << one.error << two.error;
  EXPECT_EQ(two.world->physics.RobotRegion(0), 0);
  RunTicks(*one.world, 100);
  RunTicks(*two.world, 100);
  const Pose2 a = one.world->physics.RobotPose(0), b = two.world->physics.RobotPose(0);
  EXPECT_EQ(two.world->physics.RobotRegion(0), 1);
  // Migration loses Box2D's warm-start impulses, nothing else: the same drive, to a micrometre.
  EXPECT_NEAR(b.x, 0.5, 0.005);
  EXPECT_NEAR(b.x, a.x, 1e-6);
  EXPECT_NEAR(b.y, a.y, 1e-6);
  EXPECT_NEAR(b.yaw, a.yaw, 1e-6);
}

// Two robots meet head-on at the boundary: each world pushes its robot against the other's
// ghost, so neither passes through the other and both stop touching at x = ∓ radius (within
// a millimetre or two: each is pushed back as by a wall, then drives on).
TEST(RegionStepping, RobotsMeetingAtTheBoundaryCollide) {
  TempDir d;
  d.Write("east.lua", Drive(10, 10));
  d.Write("west.lua", Drive(10, 10));
  const std::string controllers = WheelsController("e", "east.lua") + WheelsController("w", "west.lua");
  const std::string arena = FootBot("a", -0.4, 0, 0, "e") + FootBot("b", 0.4, 0, 180, "w");
  Scene s = Load(d, WithEngines(Experiment(arena, controllers, 100), kTwoEngines));
  ASSERT_TRUE(s.ok()) << s.error;
  for (int t = 0; t < 100; ++t) {  // they meet after ~3.2 s, then push for 6.8 s
    Step(*s.world);
    const Pose2 a = s.world->physics.RobotPose(0), b = s.world->physics.RobotPose(1);
    ASSERT_GE(b.x - a.x, 2 * footbot::kRadius - 0.005) << "tick " << t + 1;
  }
  const Pose2 a = s.world->physics.RobotPose(0), b = s.world->physics.RobotPose(1);
  EXPECT_NEAR(a.x, -footbot::kRadius, 0.01);
  EXPECT_NEAR(b.x, footbot::kRadius, 0.01);
  EXPECT_EQ(s.world->physics.RobotRegion(0), 0);
  EXPECT_EQ(s.world->physics.RobotRegion(1), 1);
}

// A wall owned by the west region stops a robot of the east one.
TEST(RegionStepping, StaticObstacleAcrossTheBoundaryStopsRobots) {
  TempDir d;
  d.Write("go.lua", Drive(-10, -10));  // west, backwards
  const std::string arena =
      FootBot("fb0", 0.5, 0, 0, "c") + Box("wall", -0.05, 0, 0.2, 2, 0.5);  // wall: x in [-0.15, 0.05]
  Scene s = Load(d, WithEngines(Experiment(arena, WheelsController("c", "go.lua"), 100), kTwoEngines));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 100);
  EXPECT_NEAR(s.world->physics.RobotPose(0).x, 0.05 + footbot::kRadius, 0.01);
  EXPECT_EQ(s.world->physics.RobotRegion(0), 1);
}

const char* kGripController =
    "<lua_controller id=\"g\"><actuators><differential_steering implementation=\"default\"/>"
    "<footbot_gripper implementation=\"default\"/></actuators><sensors/><params script=\"" ESSAIM_SOURCE_DIR
    "/tests/support/idle.lua\"/></lua_controller>";

void Wheels(RobotState& r, double left_cm, double right_cm) {
  r.cmd.wheel_left = left_cm * 0.01;
  r.cmd.wheel_right = right_cm * 0.01;
  r.cmd.wheels_new = true;
}

// A robot grips a cylinder of the other region (it joins the robot's world at once), tows it
// across the boundary and back: the group migrates whole and the grip holds.
TEST(RegionStepping, GripAcrossTheBoundaryHoldsThroughMigrations) {
  TempDir d;
  const double held = footbot::kRadius + 0.05 + 0.002;  // centre to centre, cylinder r = 5 cm
  const std::string arena =
      FootBot("fb", -0.1, 0, 0, "g") +
      "<cylinder id=\"c\" radius=\"0.05\" height=\"0.1\" movable=\"true\" mass=\"0.1\"><body position=\"" +
      std::to_string(-0.1 + held) + ",0,0\"/></cylinder>";
  Scene s = Load(d, WithEngines(Experiment(arena, kGripController, 1000), kTwoEngines));
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  auto gap = [&] {
    const Pose2 r = w.physics.RobotPose(0), c = w.physics.ObstaclePose(0);
    return std::hypot(c.x - r.x, c.y - r.y);
  };
  w.robots[0].cmd.gripper_aperture = kPi / 2;  // lock_positive
  Step(w);
  ASSERT_EQ(w.physics.Gripped(0).kind, BodyKind::Obstacle);
  EXPECT_EQ(w.physics.RobotRegion(0), 0);
  Wheels(w.robots[0], 10, 10);  // east: the robot crosses x = 0 after ~1 s
  RunTicks(w, 30);
  EXPECT_EQ(w.physics.RobotRegion(0), 1);
  EXPECT_NEAR(w.physics.RobotPose(0).x, 0.2, 0.01);
  EXPECT_NEAR(gap(), held, 0.005);
  Wheels(w.robots[0], -10, -10);  // back west, towing the cylinder behind the boundary
  RunTicks(w, 50);
  EXPECT_EQ(w.physics.RobotRegion(0), 0);
  EXPECT_NEAR(w.physics.RobotPose(0).x, -0.3, 0.01);
  EXPECT_NEAR(gap(), held, 0.005);
  EXPECT_EQ(w.physics.Gripped(0).kind, BodyKind::Obstacle);
}

// A crowd in a 2 × 2 m pen across the boundary, a movable cylinder among them.
std::string Crowd(const std::string& engines) {
  const std::string arena = Box("n", 0, 1, 2.2, 0.1, 0.5) + Box("s", 0, -1, 2.2, 0.1, 0.5) +
                            Box("e", 1, 0, 0.1, 2, 0.5) + Box("w", -1, 0, 0.1, 2, 0.5) +
                            "<cylinder id=\"m\" radius=\"0.1\" height=\"0.2\" movable=\"true\" mass=\"0.5\"><body "
                            "position=\"0.05,0.3,0\"/></cylinder>"
                            "<distribute><position method=\"uniform\" min=\"-0.9,-0.9,0\" max=\"0.9,0.9,0\"/>"
                            "<orientation method=\"uniform\" min=\"0,0,0\" max=\"360,0,0\"/>"
                            "<entity quantity=\"30\" max_trials=\"100\"><foot-bot id=\"fb\"><controller "
                            "config=\"c\"/></foot-bot></entity></distribute>";
  return WithEngines(Experiment(arena, WheelsController("c", "wander.lua"), 300, 5), engines);
}

struct CrowdRun {
  uint64_t hash = 0;
  int migrations = 0;  // region changes seen at the ends of ticks
  double closest = 1;  // m, least distance between two robot centres on opposite sides
};

CrowdRun RunCrowd(const std::string& engines, int threads) {
  TempDir d;
  d.Write("wander.lua", WanderController());
  LoadOptions lo;
  lo.threads = threads;
  Scene s = Load(d, Crowd(engines), lo);
  CrowdRun out;
  EXPECT_TRUE(s.ok()) << s.error;
  if (!s.ok()) return out;
  const PhysicsWorld& p = s.world->physics;
  std::vector<int> region(p.RobotCount());
  for (int i = 0; i < p.RobotCount(); ++i) region[i] = p.RobotRegion(i);
  while (Step(*s.world) == StepStatus::Running) {
    for (int i = 0; i < p.RobotCount(); ++i) {
      out.migrations += p.RobotRegion(i) != region[i];
      region[i] = p.RobotRegion(i);
      for (int j = 0; j < i; ++j)
        if ((p.RobotPose(i).x < 0) != (p.RobotPose(j).x < 0))
          out.closest = std::min(out.closest,
                                 std::hypot(p.RobotPose(i).x - p.RobotPose(j).x, p.RobotPose(i).y - p.RobotPose(j).y));
    }
  }
  out.hash = PoseHash(*s.world);
  return out;
}

TEST(RegionStepping, ThreadCountDoesNotChangeResults) {
  const CrowdRun one = RunCrowd(kTwoEngines, 1);
  EXPECT_GT(one.migrations, 10);  // the test crosses the boundary often
  // Robots on opposite sides touch but never overlap beyond Box2D's slop.
  EXPECT_LT(one.closest, 2 * footbot::kRadius + 0.01);
  EXPECT_GT(one.closest, 2 * footbot::kRadius - 0.02);
  EXPECT_EQ(RunCrowd(kTwoEngines, 2).hash, one.hash);
  EXPECT_EQ(RunCrowd(kTwoEngines, 4).hash, one.hash);
}

TEST(RegionStepping, StripsAreDeterministicToo) {
  const char* strips = "<dynamics2d id=\"dyn2d\" iterations=\"10\" regions=\"4\"/>";
  const CrowdRun one = RunCrowd(strips, 1);
  EXPECT_GT(one.migrations, 10);
  EXPECT_EQ(RunCrowd(strips, 2).hash, one.hash);
}

}  // namespace
}  // namespace essaim
