// Robots that touch nothing are moved outside Box2D (physics_dormant_robots.cpp) only while
// that gives Box2D's own result: a wandering swarm that meets walls, boxes and itself must
// move bit for bit the same with dormancy off, and dormancy must have carried a good part of
// the sub-steps for the comparison to mean something.
#include <gtest/gtest.h>

#include <string>

#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

/// 60 robots on a 10 x 6 grid in a walled 10 m arena with boxes among them, wandering fast
/// (30 cm/s, sharp random turns) so that many meet something within the run.
std::string WanderingSwarm() {
  std::string arena;
  arena += Box("n", 0, 5, 10, 0.1, 0.5) + Box("s", 0, -5, 10, 0.1, 0.5);
  arena += Box("e", 5, 0, 0.1, 10, 0.5) + Box("w", -5, 0, 0.1, 10, 0.5);
  for (int i = 0; i < 6; ++i)
    arena += Box("b" + std::to_string(i), -3.5 + 1.4 * i, -0.5 + 0.1 * (i % 3), 0.3, 0.3, 0.5);
  for (int i = 0; i < 60; ++i)
    arena += FootBot("fb" + std::to_string(i), -4 + 0.8 * (i % 10), -4 + 1.4 * (i / 10), 37 * i, "c");
  return Experiment(arena, WheelsController("c", "wander.lua"), 300, 7);
}

struct SwarmEnd {
  uint64_t poses = 0;
  std::string velocities;  // every robot's linear and angular velocity, as bytes
  int64_t dormant = 0;
};

SwarmEnd RunSwarm(bool dormancy) {
  TempDir d;
  d.Write("wander.lua",
          "function init() robot.wheels.set_velocity(30, 30) end\n" + WanderController("0.2", "20", "30"));
  Scene s = Load(d, WanderingSwarm());
  EXPECT_TRUE(s.ok()) << s.error;
  if (!s.ok()) return {};
  s.world->physics.SetDormancy(dormancy);
  RunTicks(*s.world, 300);
  SwarmEnd r;
  r.poses = PoseHash(*s.world);
  for (int i = 0; i < s.world->physics.RobotCount(); ++i) {
    const Vec2 v = s.world->physics.RobotVelocity(i);
    const double w = s.world->physics.RobotAngularVelocity(i);
    r.velocities.append(reinterpret_cast<const char*>(&v), sizeof v);
    r.velocities.append(reinterpret_cast<const char*>(&w), sizeof w);
  }
  r.dormant = s.world->physics.DormantSubsteps();
  return r;
}

TEST(DormantRobots, MoveBitForBitAsBox2DWouldMoveThem) {
  const SwarmEnd on = RunSwarm(true);
  const SwarmEnd off = RunSwarm(false);
  EXPECT_EQ(on.poses, off.poses);
  EXPECT_EQ(on.velocities, off.velocities);
  EXPECT_EQ(off.dormant, 0);
  const int64_t robot_substeps = 60 * 300 * 10;
  EXPECT_GT(on.dormant, robot_substeps / 5);       // a good part slept ...
  EXPECT_LT(on.dormant, robot_substeps * 9 / 10);  // ... and Box2D stepped the rest
}

}  // namespace
}  // namespace essaim
