// Rays against a gathered candidate list (PhysicsWorld::GatherRayCandidates + CastRay of
// candidates) answer exactly what a ray through Box2D's tree answers: same hit or
// miss, same distance to the last bit, for the proximity and scanner rays of crowded robots
// among rotated boxes, tiled walls, cylinders and pushed movable boxes.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

// Walls, boxes and cylinders (some movable, some below the scanner) among `robots` foot-bots
// placed uniformly in the square of half-side `half` (m).
std::string Crowd(int robots, uint64_t seed, double half = 2.5) {
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
  std::snprintf(buf, sizeof buf, "<distribute><position method=\"uniform\" min=\"%g,%g,0\" max=\"%g,%g,0\"/>", -half,
                -half, half, half);
  arena += buf;
  arena += "<orientation method=\"uniform\" min=\"0,0,0\" max=\"360,0,0\"/><entity quantity=\"" +
           std::to_string(robots) +
           "\" max_trials=\"100\"><foot-bot id=\"fb\"><controller config=\"c\"/></foot-bot>"
           "</entity></distribute>";
  return arena;
}

TEST(RayCandidates, SameHitsAndDistancesAsTheTree) {
  TempDir d;
  // Robots wander and push movable boxes, so dynamic bodies' boxes are the swept kind.
  d.Write("wander.lua",
          "function step() robot.wheels.set_velocity(20 * robot.random.uniform(), "
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

// CastRay of candidates scans them nearest first and stops once none left can beat its
// closest hit. Pitted against Box2D's tree walk (b2World::RayCast) in a crowd as dense as
// foraging-300's (~15 foot-bots per m², shoving each other): rays from anywhere within the
// body at any length the gathered disc allows, and rays grazing the neighbours' circles, where
// Box2D's float fractions are least precise. Same hit or miss, same distance to the last bit.
TEST(RayCandidates, NearestFirstStopMatchesTheTreeInADenseCrowd) {
  TempDir d;
  d.Write("wander.lua",
          "function step() robot.wheels.set_velocity(20 * robot.random.uniform(), "
          "20 * robot.random.uniform()) end\n");
  Scene s = Load(d, Experiment(Crowd(300, 7, 2.2), WheelsController("c", "wander.lua"), 40, 7));
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  Rng rng;
  rng.Seed(77);
  RayCandidates near_shapes;
  std::vector<int> neighbours;
  int rays = 0, hits = 0, grazing = 0;
  auto check = [&](const Vec2& from, const Vec2& to, double z, int self) {
    const RayHit tree = w.physics.CastRay(from, to, z, self);
    const RayHit listed = w.physics.CastRay(near_shapes, from, to);
    ++rays;
    hits += tree.Hit();
    ASSERT_EQ(tree.Hit(), listed.Hit()) << "robot " << self << " z " << z << " ray " << rays;
    if (tree.Hit()) {
      ASSERT_EQ(tree.distance, listed.distance) << "robot " << self << " z " << z << " ray " << rays;
    }
  };
  for (int round = 0; round < 2; ++round) {
    RunTicks(w, round == 0 ? 3 : 20);
    for (int i = 0; i < w.physics.RobotCount(); ++i) {
      const Pose2 p = w.physics.RobotPose(i);
      const Vec2 c(p.x, p.y);
      for (double z : {footbot::kProximityElevation, footbot::kScannerElevation}) {
        const double radius = footbot::kRadius + (z < 0.1 ? 0.1 : 1.42);
        w.physics.GatherRayCandidates(c, radius, z, i, &near_shapes);
        for (int k = 0; k < 24; ++k) {  // anywhere in the body, any direction, as long as the disc allows
          const double rho = rng.Uniform(0.0, footbot::kRadius), phi = rng.Uniform(-kPi, kPi);
          const double a = rng.Uniform(-kPi, kPi), len = rng.Uniform(0.0, radius - rho);
          const Vec2 from = c + rho * Vec2(std::cos(phi), std::sin(phi));
          check(from, from + len * Vec2(std::cos(a), std::sin(a)), z, i);
          if (::testing::Test::HasFatalFailure()) return;
        }
        // From the body surface, tangent to each neighbour's circle, nudged by up to 1e-4 rad.
        w.physics.RobotsNear(c, radius, &neighbours);
        for (int j : neighbours) {
          if (j == i) continue;
          const Pose2 q = w.physics.RobotPose(j);
          const Vec2 dq(q.x - p.x, q.y - p.y);
          if (dq.norm() <= 2 * footbot::kRadius || dq.norm() + footbot::kRadius > radius) continue;
          const double toward = std::atan2(dq.y(), dq.x());
          const double from_angle = toward + rng.Uniform(-0.3, 0.3);
          const Vec2 from = c + footbot::kRadius * Vec2(std::cos(from_angle), std::sin(from_angle));
          const Vec2 e = Vec2(q.x, q.y) - from;
          const double half_width = std::asin(std::min(1.0, footbot::kRadius / e.norm()));
          for (double side : {-1.0, 1.0})
            for (double nudge : {0.0, 1e-7, -1e-7, 1e-5, -1e-5, 1e-4, -1e-4}) {
              const double a = std::atan2(e.y(), e.x()) + side * half_width + nudge;
              check(from, from + (radius - footbot::kRadius) * Vec2(std::cos(a), std::sin(a)), z, i);
              if (::testing::Test::HasFatalFailure()) return;
              ++grazing;
            }
        }
      }
    }
  }
  EXPECT_GT(rays, 500000);
  EXPECT_GT(grazing, 400000);
  EXPECT_GT(hits, rays / 3);  // dense: most rays hit something
}

// A scanner's long sensor casts its six sweep rays against the candidates near the sector
// they sweep (PhysicsWorld::GatherWedgeCandidates). In the dense crowd among tiled walls and
// rotated boxes: sectors of every width up to a quarter turn (zero included), rays on both
// edges and inside, rays at every corner of every box in reach (nudged by up to 1e-4 rad) as a
// sector's edge or its only direction, each from the body surface as the scanner casts them.
// Same hit or miss, same distance to the last bit as Box2D's tree; and the sectors keep only a
// fraction of the disc's candidates.
TEST(RayCandidates, WedgeKeepsEveryShapeItsRaysCanHit) {
  TempDir d;
  d.Write("wander.lua",
          "function step() robot.wheels.set_velocity(20 * robot.random.uniform(), "
          "20 * robot.random.uniform()) end\n");
  Scene s = Load(d, Experiment(Crowd(300, 11, 2.2), WheelsController("c", "wander.lua"), 40, 11));
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  const std::vector<ObstacleDef>& obstacles = s.model->obstacles;
  ASSERT_EQ(static_cast<int>(obstacles.size()), w.physics.ObstacleCount());
  Rng rng;
  rng.Seed(78);
  RayCandidates all, wedge;
  const double z = footbot::kScannerElevation, length = 1.42, r = footbot::kRadius;
  int rays = 0, hits = 0, corners = 0;
  size_t all_items = 0, wedge_items = 0;
  auto check = [&](const Pose2& p, double a, double len, int self) {
    const Vec2 u(std::cos(a), std::sin(a));
    const Vec2 from(p.x + r * u.x(), p.y + r * u.y()), to = from + len * u;
    const RayHit tree = w.physics.CastRay(from, to, z, self);
    const RayHit listed = w.physics.CastRay(wedge, from, to);
    ++rays;
    hits += tree.Hit();
    ASSERT_EQ(tree.Hit(), listed.Hit()) << "robot " << self << " ray " << rays;
    if (tree.Hit()) {
      ASSERT_EQ(tree.distance, listed.distance) << "robot " << self << " ray " << rays;
    }
  };
  for (int round = 0; round < 2; ++round) {
    RunTicks(w, round == 0 ? 3 : 20);
    for (int i = 0; i < w.physics.RobotCount(); ++i) {
      const Pose2 p = w.physics.RobotPose(i);
      w.physics.GatherRayCandidates({p.x, p.y}, r + length, z, i, &all);
      for (int k = 0; k < 8; ++k) {  // random wedges, as the sweep gives them (span >= 0)
        const double a0 = rng.Uniform(-kPi, kPi), width = k == 0 ? 0.0 : rng.Uniform(0.0, kPi / 2);
        w.physics.GatherWedgeCandidates({p.x, p.y}, r + length, {std::cos(a0), std::sin(a0)},
                                        {std::cos(a0 + width), std::sin(a0 + width)}, z, i, &wedge);
        all_items += all.items.size();
        wedge_items += wedge.items.size();
        for (int j = 0; j <= 5; ++j) {
          check(p, a0 + j * width / 5, length, i);
          if (::testing::Test::HasFatalFailure()) return;
        }
        check(p, a0 + rng.Uniform(0.0, width), rng.Uniform(0.0, length), i);
        if (::testing::Test::HasFatalFailure()) return;
      }
      // Rays at each box corner in reach, and along the faces: the ray is a wedge's edge.
      for (size_t o = 0; o < obstacles.size(); ++o) {
        if (obstacles[o].kind != ShapeKind::Box) continue;
        const Pose2 q = w.physics.ObstaclePose(static_cast<int>(o));
        const double hx = obstacles[o].size_x / 2, hy = obstacles[o].size_y / 2;
        for (int corner = 0; corner < 4; ++corner) {
          const double lx = corner & 1 ? hx : -hx, ly = corner & 2 ? hy : -hy;
          const Vec2 e(q.x + lx * std::cos(q.yaw) - ly * std::sin(q.yaw) - p.x,
                       q.y + lx * std::sin(q.yaw) + ly * std::cos(q.yaw) - p.y);
          if (e.norm() > r + length || e.norm() < r) continue;
          ++corners;
          for (double nudge : {0.0, 1e-7, -1e-7, 1e-5, -1e-5, 1e-4, -1e-4}) {
            const double a = std::atan2(e.y(), e.x()) + nudge;
            const Vec2 u(std::cos(a), std::sin(a));
            const bool left = corner % 2 == 0;  // the ray opens or closes the wedge
            const double b = left ? a + 0.3 : a - 0.3;
            const Vec2 v(std::cos(b), std::sin(b));
            w.physics.GatherWedgeCandidates({p.x, p.y}, r + length, left ? u : v, left ? v : u, z, i, &wedge);
            check(p, a, length, i);
            if (::testing::Test::HasFatalFailure()) return;
            w.physics.GatherWedgeCandidates({p.x, p.y}, r + length, u, u, z, i, &wedge);  // a single direction
            check(p, a, length, i);
            if (::testing::Test::HasFatalFailure()) return;
          }
        }
      }
    }
  }
  EXPECT_GT(rays, 100000);
  EXPECT_GT(corners, 1000);
  EXPECT_GT(hits, rays / 3);
  EXPECT_LT(wedge_items * 3, all_items);  // the point of it: a sector keeps a third at most
}

// Long walls (32 m, tiled by the physics) in a sparse arena, some rotated: rays parallel to a
// wall's face at distances straddling it, along it, at its ends and corners, from robots near
// it, through the wedge of a long sensor's sweep. Same hits as Box2D's tree.
TEST(RayCandidates, WedgeAlongLongAndRotatedWalls) {
  TempDir d;
  d.Write("still.lua", "function step() end\n");
  std::string arena =
      "<box id=\"n\" size=\"32,0.1,0.5\" movable=\"false\"><body position=\"0,1,0\"/></box>"
      "<box id=\"r\" size=\"12,0.2,0.5\" movable=\"false\"><body position=\"0,-1,0\" orientation=\"17,0,0\"/></box>"
      "<box id=\"e\" size=\"0.1,9,0.5\" movable=\"false\"><body position=\"2,0,0\" orientation=\"90,0,0\"/></box>";
  // Robots anywhere clear of the walls (x, y, yaw in degrees, half sizes), down to 1 mm away.
  const double walls[3][5] = {{0, 1, 0, 16, 0.05}, {0, -1, 17, 6, 0.1}, {2, 0, 90, 0.05, 4.5}};
  auto clear = [&](double x, double y) {
    for (const auto& b : walls) {
      const double a = DegToRad(b[2]), dx = x - b[0], dy = y - b[1];
      const double lx = std::abs(dx * std::cos(a) + dy * std::sin(a)),
                   ly = std::abs(-dx * std::sin(a) + dy * std::cos(a));
      const double ex = std::max(lx - b[3], 0.0), ey = std::max(ly - b[4], 0.0);
      if (ex * ex + ey * ey < std::pow(footbot::kRadius + 0.001, 2)) return false;
    }
    return true;
  };
  Rng place;
  place.Seed(5);
  std::vector<Vec2> placed;
  while (placed.size() < 40) {
    const Vec2 c(place.Uniform(-3, 3), place.Uniform(-3, 3));
    if (!clear(c.x(), c.y())) continue;
    bool apart = true;
    for (const Vec2& o : placed) apart = apart && (o - c).norm() > 2 * footbot::kRadius + 0.01;
    if (!apart) continue;
    arena += FootBot("fb" + std::to_string(placed.size()), c.x(), c.y(), 0, "c");
    placed.push_back(c);
  }
  Scene s = Load(d, Experiment(arena, WheelsController("c", "still.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  PhysicsWorld& ph = s.world->physics;
  const double z = footbot::kScannerElevation, length = 1.42, r = footbot::kRadius;
  RayCandidates wedge;
  Rng rng;
  rng.Seed(9);
  int rays = 0, hits = 0;
  for (int i = 0; i < ph.RobotCount(); ++i) {
    const Pose2 p = ph.RobotPose(i);
    for (int k = 0; k < 2000; ++k) {
      // Directions near the walls' own (0, 17°, 90° and their opposites) and anywhere.
      const double base = (k % 5) * kPi / 2 + (k % 5 == 4 ? DegToRad(17) : 0);
      const double a = k % 3 == 0 ? rng.Uniform(-kPi, kPi) : base + (k % 2 ? 1 : -1) * rng.Uniform(0.0, 1e-3);
      const double width = rng.Uniform(0.0, kPi / 2), before = rng.Uniform(0.0, width);
      ph.GatherWedgeCandidates({p.x, p.y}, r + length, {std::cos(a - before), std::sin(a - before)},
                               {std::cos(a - before + width), std::sin(a - before + width)}, z, i, &wedge);
      const Vec2 u(std::cos(a), std::sin(a));
      const Vec2 from(p.x + r * u.x(), p.y + r * u.y()), to = from + length * u;
      const RayHit tree = ph.CastRay(from, to, z, i), listed = ph.CastRay(wedge, from, to);
      ++rays;
      hits += tree.Hit();
      ASSERT_EQ(tree.Hit(), listed.Hit()) << "robot " << i << " ray " << k;
      if (tree.Hit()) {
        ASSERT_EQ(tree.distance, listed.distance) << "robot " << i << " ray " << k;
      }
    }
  }
  EXPECT_GT(hits, rays / 10);
}

// The candidates come from a grid rebuilt after shapes move: a teleported robot, an added,
// moved or removed obstacle is seen where it is now, without a physics step in between.
TEST(RayCandidates, FollowTeleportsAndObstaclesAddedMovedOrRemoved) {
  TempDir d;
  d.Write("still.lua", "function step() end\n");
  Scene s = Load(
      d, Experiment(FootBot("fb0", 0, 0, 0, "c") + FootBot("fb1", 0.5, 0, 0, "c"), WheelsController("c", "still.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  PhysicsWorld& ph = s.world->physics;
  const double z = footbot::kScannerElevation, r = footbot::kRadius;
  RayCandidates c;
  // Distance along a 1.42 m ray from fb0's surface in direction (dx, dy); -1 for a miss.
  auto cast = [&](double dx, double dy) {
    ph.GatherRayCandidates({0, 0}, r + 1.42, z, 0, &c);
    const Vec2 from(r * dx, r * dy), to = from + 1.42 * Vec2(dx, dy);
    const RayHit listed = ph.CastRay(c, from, to), tree = ph.CastRay(from, to, z, 0);
    EXPECT_EQ(listed.Hit(), tree.Hit());
    EXPECT_EQ(listed.distance, tree.distance);
    return listed.Hit() ? listed.distance : -1.0;
  };
  EXPECT_NEAR(cast(1, 0), 0.5 - 2 * r, 1e-6);
  ph.SetRobotPose(1, {1.0, 0, 0});
  EXPECT_NEAR(cast(1, 0), 1.0 - 2 * r, 1e-6);
  ObstacleDef post;
  post.kind = ShapeKind::Cylinder;
  post.radius = 0.05;
  post.height = 0.5;
  post.pose = {0.4, 0, 0};
  const int index = ph.AddObstacle(post);
  EXPECT_NEAR(cast(1, 0), 0.4 - 0.05 - r, 1e-6);
  EXPECT_EQ(cast(0, 1), -1.0);
  ph.SetObstaclePose(index, {0, 0.6, 0});
  EXPECT_NEAR(cast(1, 0), 1.0 - 2 * r, 1e-6);
  EXPECT_NEAR(cast(0, 1), 0.6 - 0.05 - r, 1e-6);
  ph.RemoveObstacle(index);
  EXPECT_EQ(cast(0, 1), -1.0);
  EXPECT_NEAR(cast(1, 0), 1.0 - 2 * r, 1e-6);
}

TEST(RayCandidates, ExcludedRobotAndShapesBelowTheRayAreNotCandidates) {
  TempDir d;
  d.Write("still.lua", "function step() end\n");
  const std::string arena =
      FootBot("fb0", 0, 0, 0, "c") + FootBot("fb1", 0.3, 0, 0, "c") +
      "<box id=\"low\" size=\"0.1,0.1,0.03\" movable=\"false\"><body position=\"0,0.3,0\"/></box>";
  Scene s = Load(d, Experiment(arena, WheelsController("c", "still.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  RayCandidates c;
  s.world->physics.GatherRayCandidates({0, 0}, 0.5, 0.06, 0, &c);
  ASSERT_EQ(c.items.size(), 2u);  // fb1's body and gripper disc only: not fb0's, not the 3 cm box
  s.world->physics.GatherRayCandidates({0, 0}, 0.5, 0.02, 0, &c);
  EXPECT_EQ(c.items.size(), 3u);  // the low box too
  s.world->physics.GatherRayCandidates({0, 0}, 0.1, 0.06, 0, &c);
  EXPECT_TRUE(c.items.empty());  // fb1's body starts at 0.215 m
  const RayHit h = s.world->physics.CastRay(RayCandidates(), {0, 0}, {1, 0});
  EXPECT_FALSE(h.Hit());
}

}  // namespace
}  // namespace essaim
