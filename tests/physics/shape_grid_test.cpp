// ShapeGrid (physics/shape_grid.h): every circle that can touch a query disc is reported,
// each exactly once, whatever the circles' sizes and places — checked against brute force.
#include "physics/shape_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>

#include "core/rng.h"

namespace essaim {
namespace {

// Reported circles (by their `robot` field, used here as an id) for the disc (x, y, radius).
std::map<int, int> Query(const ShapeGrid& grid, double x, double y, double radius) {
  std::map<int, int> seen;
  grid.ForEachNear(x, y, radius, [&](const GridCircle& c) { ++seen[c.robot]; });
  return seen;
}

void ExpectAllTouchingReportedOnce(const ShapeGrid& grid, const std::vector<GridCircle>& circles, double x, double y,
                                   double radius) {
  const std::map<int, int> seen = Query(grid, x, y, radius);
  for (const auto& [id, count] : seen) ASSERT_EQ(count, 1) << "circle " << id << " reported twice";
  for (const GridCircle& c : circles) {
    const double d = std::hypot(c.cx - x, c.cy - y);
    if (d <= c.r + radius) ASSERT_EQ(seen.count(c.robot), 1u) << "circle " << c.robot << " missed";
  }
}

TEST(ShapeGrid, ReportsEveryTouchingCircleOnceAmongMixedSizes) {
  Rng rng;
  rng.Seed(5);
  std::vector<GridCircle> circles;
  ShapeGrid grid;
  for (int i = 0; i < 600; ++i) {
    GridCircle c;
    c.cx = rng.Uniform(-6, 6);
    c.cy = rng.Uniform(-4, 4);
    // Mostly foot-bot sized, some wall pieces and big cylinders spanning many cells.
    c.r = i % 10 == 0 ? rng.Uniform(0.4, 2.0) : rng.Uniform(0.01, 0.1);
    c.robot = i;
    circles.push_back(c);
    grid.Add(c);
  }
  grid.Build();
  EXPECT_GT(grid.Columns(), 20);  // a real grid, not one cell
  for (int q = 0; q < 2000; ++q) {
    const double radius = q % 2 ? 1.51 : 0.19;
    ExpectAllTouchingReportedOnce(grid, circles, rng.Uniform(-8, 8), rng.Uniform(-6, 6), radius);
    if (HasFatalFailure()) return;
  }
  // Beyond the grid's edges (queries clamped to the border cells).
  ExpectAllTouchingReportedOnce(grid, circles, 100, 100, 1.5);
}

TEST(ShapeGrid, AFarOutlierGrowsTheCellsInsteadOfTheGrid) {
  std::vector<GridCircle> circles;
  ShapeGrid grid;
  for (int i = 0; i < 50; ++i) {
    GridCircle c;
    c.cx = 0.3 * (i % 10);
    c.cy = 0.3 * (i / 10);
    c.r = 0.085;
    c.robot = i;
    circles.push_back(c);
  }
  GridCircle far;  // a robot flung a million km away by an exploded simulation
  far.cx = 1e9;
  far.cy = -1e9;
  far.r = 0.085;
  far.robot = 50;
  circles.push_back(far);
  for (const GridCircle& c : circles) grid.Add(c);
  grid.Build();
  EXPECT_LE(static_cast<double>(grid.Columns()) * grid.Rows(), 4096);
  ExpectAllTouchingReportedOnce(grid, circles, 1, 1, 1.51);
  ExpectAllTouchingReportedOnce(grid, circles, 1e9, -1e9, 0.19);
}

TEST(ShapeGrid, NonFiniteCirclesAndQueriesAreHarmless) {
  ShapeGrid grid;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  GridCircle ok;
  ok.r = 0.1;
  ok.robot = 1;
  GridCircle bad = ok;
  bad.cx = nan;
  bad.robot = 2;
  GridCircle huge = ok;
  huge.cx = 1.7e308;
  huge.robot = 3;
  grid.Add(ok);
  grid.Add(bad);  // dropped
  grid.Add(huge);
  grid.Build();
  const std::map<int, int> seen = Query(grid, 0, 0, 0.5);
  EXPECT_EQ(seen.count(1), 1u);
  EXPECT_EQ(seen.count(2), 0u);
  Query(grid, nan, nan, 0.5);  // no crash, no endless loop
  ShapeGrid empty;
  empty.Build();
  EXPECT_TRUE(Query(empty, 0, 0, 1).empty());
}

}  // namespace
}  // namespace essaim
