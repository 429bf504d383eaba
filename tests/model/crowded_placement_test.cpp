// <distribute> at scale: 20 000 foot-bots placed among 2 000 turned boxes and cylinders in a
// 60 m square, crowded enough that many draws overlap and are retried. Every entity stands
// inside the square, no two overlap (checked by a sweep over x, independent of the
// placement grid), and the poses for the seed are those essaim has always drawn.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "model/distribute.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

constexpr int kRobots = 20000, kBoxes = 1000, kCylinders = 1000;
constexpr double kHalf = 30;  // m: the generators' square is [-30, 30]²

std::string Distribute(const std::string& orientation, int quantity, const std::string& entity, int trials) {
  return "<distribute><position method=\"uniform\" min=\"-30,-30,0\" max=\"30,30,0\"/>"
         "<orientation method=\"" +
         orientation + "\"/><entity quantity=\"" + std::to_string(quantity) + "\" max_trials=\"" +
         std::to_string(trials) + "\">" + entity + "</entity></distribute>";
}

std::string CrowdedArena(int trials = 100) {
  const std::string turned = "uniform\" min=\"0,0,0\" max=\"360,0,0", upright = "constant\" values=\"0,0,0";
  return "<argos-configuration>"
         "<framework><system max_entities=\"30000\"/>"
         "<experiment length=\"1\" ticks_per_second=\"10\" random_seed=\"28\"/></framework>"
         "<controllers><lua_controller id=\"c\"><actuators><differential_steering implementation=\"default\"/>"
         "</actuators><sensors/><params script=\"c.lua\"/></lua_controller></controllers>"
         "<arena size=\"64,64,1\" center=\"0,0,0.5\">" +
         Distribute(turned, kBoxes, "<box id=\"b\" size=\"0.6,0.2,0.5\" movable=\"false\"/>", trials) +
         Distribute(upright, kCylinders, "<cylinder id=\"cy\" radius=\"0.2\" height=\"0.5\" movable=\"false\"/>",
                    trials) +
         Distribute(turned, kRobots, "<foot-bot id=\"fb\"><controller config=\"c\"/></foot-bot>", trials) +
         "</arena><physics_engines><dynamics2d id=\"dyn2d\"/></physics_engines><media/></argos-configuration>";
}

std::vector<Footprint> Footprints(const Model& m) {
  std::vector<Footprint> all;
  for (const ObstacleDef& o : m.obstacles) all.push_back(ObstacleFootprint(o));
  for (const RobotDef& r : m.robots) {
    Footprint f;
    f.center = Vec2(r.pose.x, r.pose.y);
    f.radius = footbot::kRadius;
    all.push_back(f);
  }
  return all;
}

/// Radius of a disc about the centre that holds the footprint.
double Reach(const Footprint& f) { return f.is_circle ? f.radius : std::hypot(f.half_x, f.half_y); }

/// Pairs that overlap, found by sorting on x and testing each footprint against those that
/// follow it within the widest reach.
int OverlappingPairs(const std::vector<Footprint>& all) {
  std::vector<int> order(all.size());
  double widest = 0;
  for (size_t i = 0; i < all.size(); ++i) {
    order[i] = static_cast<int>(i);
    widest = std::max(widest, Reach(all[i]));
  }
  std::sort(order.begin(), order.end(), [&](int a, int b) { return all[a].center.x() < all[b].center.x(); });
  int pairs = 0;
  for (size_t a = 0; a < order.size(); ++a) {
    const Footprint& f = all[order[a]];
    for (size_t b = a + 1; b < order.size() && all[order[b]].center.x() - f.center.x() < Reach(f) + widest; ++b)
      pairs += FootprintsOverlap(f, all[order[b]]);
  }
  return pairs;
}

uint64_t PoseHash(const Model& m) {
  uint64_t h = 1469598103934665603ull;  // FNV-1a over the poses' bits
  auto mix = [&](double v) {
    uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    h = (h ^ bits) * 1099511628211ull;
  };
  for (const ObstacleDef& o : m.obstacles) mix(o.pose.x), mix(o.pose.y), mix(o.pose.yaw);
  for (const RobotDef& r : m.robots) mix(r.pose.x), mix(r.pose.y), mix(r.pose.yaw);
  return h;
}

TEST(CrowdedPlacement, TwentyThousandRobotsStandInsideTheSquareAndApart) {
  TempDir d;
  d.Write("c.lua", "function step() end");
  ErrorList errors;
  auto m = LoadExperimentFile(d.Write("crowded.argos", CrowdedArena()), {}, &errors);
  ASSERT_TRUE(m) << errors.Format();
  ASSERT_EQ(m->robots.size(), static_cast<size_t>(kRobots));
  ASSERT_EQ(m->obstacles.size(), static_cast<size_t>(kBoxes + kCylinders));
  for (const RobotDef& r : m->robots) {
    ASSERT_TRUE(std::abs(r.pose.x) <= kHalf && std::abs(r.pose.y) <= kHalf) << r.id;
  }
  for (const ObstacleDef& o : m->obstacles) ASSERT_TRUE(std::abs(o.pose.x) <= kHalf && std::abs(o.pose.y) <= kHalf);
  EXPECT_EQ(OverlappingPairs(Footprints(*m)), 0);
  // Crowded: with no retry allowed, some draw overlaps and the load fails.
  ErrorList no_retry;
  EXPECT_FALSE(LoadExperimentFile(d.Write("no_retry.argos", CrowdedArena(0)), {}, &no_retry));
  EXPECT_NE(no_retry.Format().find("could not place"), std::string::npos) << no_retry.Format();
}

TEST(CrowdedPlacement, TheSweepFindsOverlaps) {
  Footprint a, b, box;
  a.radius = b.radius = 0.1;
  b.center = Vec2(0.15, 0);
  box.is_circle = false;
  box.center = Vec2(-0.5, 0);
  box.half_x = 0.35, box.half_y = 0.01;  // reaches a's edge at x = -0.15, not a
  EXPECT_EQ(OverlappingPairs({a, b, box}), 1);
  box.half_x = 0.45;
  EXPECT_EQ(OverlappingPairs({box, a, b}), 2);
}

TEST(CrowdedPlacement, SameSeedPlacesWhereItAlwaysDid) {
  TempDir d;
  d.Write("c.lua", "function step() end");
  ErrorList errors;
  auto m = LoadExperimentFile(d.Write("crowded.argos", CrowdedArena()), {}, &errors);
  ASSERT_TRUE(m) << errors.Format();
  // Generated values are rounded to six significant digits, as ARGoS writes them. A change
  // in how placement finds overlaps must leave every pose where it was.
  EXPECT_EQ(m->robots.front().id, "fb0");
  EXPECT_EQ(m->robots.front().pose.x, 1.16164);
  EXPECT_EQ(m->robots.front().pose.y, -26.564);
  EXPECT_EQ(m->robots.back().pose.x, -4.68778);
  EXPECT_EQ(m->robots.back().pose.y, -27.4412);
  EXPECT_EQ(PoseHash(*m), 0xc3dcb895631e6d91ull) << std::hex << PoseHash(*m);
}

}  // namespace
}  // namespace essaim
