// Rays against a gathered candidate list (PhysicsWorld::GatherRayCandidates + CastRay of
// candidates, issue 12) answer exactly what a ray through Box2D's tree answers: same hit or
// miss, same distance to the last bit, for the proximity and scanner rays of crowded robots
// among rotated boxes, tiled walls, cylinders and pushed movable boxes.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

std::string Crowd(int robots, uint64_t seed) {
  Rng rng;
  rng.Seed(seed);
  std::string arena =
      "<box id=\"wall_n\" size=\"6,0.1,0.5\" movable=\"false\"><body position=\"0,3,0\"/></box>"
      "<box id=\"wall_s\" size=\"6,0.1,0.5\" movable=\"false\"><body position=\"0,-3,0\"/></box>"
      "<box id=\"wall_e\" size=\"0.1,6,0.5\" movable=\"false\"><body position=\"3,0,0\"/></box>"
      "<box id=\"low\" size=\"0.3,0.3,0.08\" movable=\"false\"><body position=\"-1,-1,0\"/></box>";
  char buf[320];
  for (int i = 0; i < 12; ++i) {
    std::snprintf(buf, sizeof buf,
                  "<box id=\"b%d\" size=\"%.3f,%.3f,0.3\" movable=\"%s\" mass=\"1\"><body position=\"%.3f,%.3f,0\" "
                  "orientation=\"%.1f,0,0\"/></box>",
                  i, rng.Uniform(0.05, 0.5), rng.Uniform(0.05, 0.5), i % 3 == 0 ? "true" : "false",
                  rng.Uniform(-2.5, 2.5), rng.Uniform(-2.5, 2.5), rng.Uniform(0, 360));
    arena += buf;
    std::snprintf(buf, sizeof buf,
                  "<cylinder id=\"c%d\" radius=\"%.3f\" height=\"%.3f\" movable=\"%s\" mass=\"1\"><body "
                  "position=\"%.3f,%.3f,0\"/></cylinder>",
                  i, rng.Uniform(0.03, 0.2), i % 4 == 0 ? 0.1 : 0.5, i % 3 == 1 ? "true" : "false",
                  rng.Uniform(-2.5, 2.5), rng.Uniform(-2.5, 2.5));
    arena += buf;
  }
  arena += "<distribute><position method=\"uniform\" min=\"-2.5,-2.5,0\" max=\"2.5,2.5,0\"/>"
           "<orientation method=\"uniform\" min=\"0,0,0\" max=\"360,0,0\"/><entity quantity=\"" +
           std::to_string(robots) + "\" max_trials=\"100\"><foot-bot id=\"fb\"><controller config=\"c\"/></foot-bot>"
           "</entity></distribute>";
  return arena;
}

TEST(RayCandidates, SameHitsAndDistancesAsTheTree) {
  TempDir d;
  // Robots wander and push movable boxes, so dynamic bodies' boxes are the swept kind.
  d.Write("wander.lua", "function step() robot.wheels.set_velocity(20 * robot.random.uniform(), "
                        "20 * robot.random.uniform()) end\n");
  int rays = 0, hits = 0;
  for (uint64_t seed : {1, 2, 3}) {
    Scene s = Load(d, Experiment(Crowd(60, seed), WheelsController("c", "wander.lua"), 40, static_cast<int>(seed)));
    ASSERT_TRUE(s.ok()) << s.error;
    World& w = *s.world;
    Rng rng;
    rng.Seed(100 + seed);
    RayCandidates near_shapes;
    for (int tick = 0; tick < 4; ++tick) {
      RunTicks(w, 10);
      for (int i = 0; i < w.physics.RobotCount(); ++i) {
        const Pose2 p = w.physics.RobotPose(i);
        for (double z : {footbot::kProximityElevation, footbot::kScannerElevation}) {
          const double reach = z < 0.1 ? 0.1 : 1.42;
          w.physics.GatherRayCandidates({p.x, p.y}, footbot::kRadius + reach, z, i, &near_shapes);
          for (int k = 0; k < 48; ++k) {
            // The sensors' own rays (body surface outwards), at random angles and lengths.
            const double a = k < 24 ? p.yaw + k * kPi / 12 : rng.Uniform(-kPi, kPi);
            const double len = k < 24 ? reach : rng.Uniform(0.0, reach);
            const Vec2 from(p.x + footbot::kRadius * std::cos(a), p.y + footbot::kRadius * std::sin(a));
            const Vec2 to(from.x() + len * std::cos(a), from.y() + len * std::sin(a));
            const RayHit tree = w.physics.CastRay(from, to, z, i);
            const RayHit listed = w.physics.CastRay(near_shapes, from, to);
            ++rays;
            hits += tree.Hit();
            ASSERT_EQ(tree.Hit(), listed.Hit()) << "robot " << i << " ray " << k << " z " << z;
            if (tree.Hit()) {
              ASSERT_EQ(tree.distance, listed.distance) << "robot " << i << " ray " << k << " z " << z;
            }
          }
        }
      }
    }
  }
  EXPECT_GT(hits, rays / 10);  // the crowd is dense enough to test hits, not only misses
}

TEST(RayCandidates, ExcludedRobotAndShapesBelowTheRayAreNotCandidates) {
  TempDir d;
  d.Write("still.lua", "function step() end\n");
  const std::string arena = FootBot("fb0", 0, 0, 0, "c") + FootBot("fb1", 0.3, 0, 0, "c") +
                            "<box id=\"low\" size=\"0.1,0.1,0.03\" movable=\"false\"><body position=\"0,0.3,0\"/></box>";
  Scene s = Load(d, Experiment(arena, WheelsController("c", "still.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  RayCandidates c;
  s.world->physics.GatherRayCandidates({0, 0}, 0.5, 0.06, 0, &c);
  ASSERT_EQ(c.items.size(), 1u);  // fb1 only: not fb0 itself, not the 3 cm box
  s.world->physics.GatherRayCandidates({0, 0}, 0.5, 0.02, 0, &c);
  EXPECT_EQ(c.items.size(), 2u);  // the low box too
  s.world->physics.GatherRayCandidates({0, 0}, 0.1, 0.06, 0, &c);
  EXPECT_TRUE(c.items.empty());  // fb1's body starts at 0.215 m
  const RayHit h = s.world->physics.CastRay(RayCandidates(), {0, 0}, {1, 0});
  EXPECT_FALSE(h.Hit());
}

}  // namespace
}  // namespace essaim
