// PlacedFootprints (model/placement.h): the grid-backed overlap test gives the same answer
// (and names the same first footprint) as testing every placed footprint, for circles and
// turned boxes, inside the arena and beyond it, while footprints are being added.
#include "model/placement.h"

#include <gtest/gtest.h>

#include "core/rng.h"

namespace essaim {
namespace {

Footprint RandomFootprint(Rng& rng, double reach) {
  Footprint f;
  f.center = Vec2(rng.Uniform(-reach, reach), rng.Uniform(-reach, reach));
  if (rng.Uniform(0, 1) < 0.7) {
    f.radius = rng.Uniform(0.02, 0.3);
  } else {
    f.is_circle = false;
    // Mostly small boxes, some long walls spanning many cells.
    const double length = rng.Uniform(0, 1) < 0.1 ? rng.Uniform(2, 8) : rng.Uniform(0.05, 0.6);
    f.half_x = length / 2;
    f.half_y = rng.Uniform(0.02, 0.3);
    f.yaw = rng.Uniform(-kPi, kPi);
  }
  return f;
}

TEST(PlacedFootprints, CollidesExactlyWhenSomePlacedFootprintOverlaps) {
  Rng rng;
  rng.Seed(17);
  PlacedFootprints placed;
  placed.Cover(Vec2(-5, -5), Vec2(5, 5));
  std::vector<Footprint> all;
  int collisions = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const Footprint f = RandomFootprint(rng, 6);  // some beyond the arena's edge
    bool brute = false;
    for (const Footprint& p : all) brute = brute || FootprintsOverlap(f, p);
    ASSERT_EQ(placed.Collides(f), brute) << "trial " << trial;
    int first = -1;
    for (size_t i = 0; i < all.size() && first < 0; ++i)
      if (FootprintsOverlap(f, all[i])) first = static_cast<int>(i);
    ASSERT_EQ(placed.FirstOverlap(f), first) << "trial " << trial;
    collisions += brute;
    if (!brute) {  // placed as the loader places: only what stands free
      placed.Add(f);
      all.push_back(f);
    }
  }
  EXPECT_GT(collisions, 100);  // the scene got crowded
  EXPECT_EQ(placed.Size(), all.size());
}

TEST(PlacedFootprints, TouchingIsNotOverlapping) {
  PlacedFootprints placed;
  placed.Cover(Vec2(-1, -1), Vec2(1, 1));
  Footprint a;
  a.radius = 0.5;
  placed.Add(a);
  Footprint b = a;
  b.center = Vec2(1, 0);  // touches a at (0.5, 0)
  EXPECT_FALSE(placed.Collides(b));
  b.center = Vec2(0.999, 0);
  EXPECT_TRUE(placed.Collides(b));
}

}  // namespace
}  // namespace essaim
