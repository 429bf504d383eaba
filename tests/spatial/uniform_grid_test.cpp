// The spatial module (src/spatial/): the uniform grid reports every item that can touch a
// query, each once where asked, whatever the items' sizes and places (checked against
// brute force on random scenes); the bucket sort is stable; segment entries into circles
// and boxes match hand-computed values.
#include "spatial/uniform_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "core/rng.h"
#include "spatial/bucket_sort.h"
#include "spatial/segment.h"

namespace essaim {
namespace {

struct Circle {
  double cx = 0, cy = 0, r = 0;
};

/// As the physics world files its ray grid: cells of 0.5 m over the circles' span, at
/// most max(4096, 4 per circle).
void FileCircles(const std::vector<Circle>& circles, UniformGrid* grid) {
  Vec2 lo = Vec2::Zero(), hi = Vec2::Zero();
  if (!circles.empty()) lo = hi = Vec2(circles[0].cx, circles[0].cy);
  for (const Circle& c : circles) {
    lo = lo.cwiseMin(Vec2(c.cx - c.r, c.cy - c.r));
    hi = hi.cwiseMax(Vec2(c.cx + c.r, c.cy + c.r));
  }
  const int n = static_cast<int>(circles.size());
  grid->CoverSpan(lo, hi, 0.5, std::max(4096.0, 4.0 * n));
  grid->FileBoxes(
      n, [&](int i) { return Vec2(circles[i].cx - circles[i].r, circles[i].cy - circles[i].r); },
      [&](int i) { return Vec2(circles[i].cx + circles[i].r, circles[i].cy + circles[i].r); });
}

// Reported circles (index -> times) for the disc (x, y, radius).
std::map<int, int> Query(const UniformGrid& grid, double x, double y, double radius) {
  std::map<int, int> seen;
  grid.ForEachOnceInBox(x - radius, y - radius, x + radius, y + radius, [&](int i) { ++seen[i]; });
  return seen;
}

void ExpectAllTouchingReportedOnce(const UniformGrid& grid, const std::vector<Circle>& circles, double x, double y,
                                   double radius) {
  const std::map<int, int> seen = Query(grid, x, y, radius);
  for (const auto& [id, count] : seen) ASSERT_EQ(count, 1) << "circle " << id << " reported twice";
  for (size_t i = 0; i < circles.size(); ++i) {
    const Circle& c = circles[i];
    const double d = std::hypot(c.cx - x, c.cy - y);
    if (d <= c.r + radius) ASSERT_EQ(seen.count(static_cast<int>(i)), 1u) << "circle " << i << " missed";
  }
}

TEST(UniformGrid, ReportsEveryTouchingCircleOnceAmongMixedSizes) {
  Rng rng;
  rng.Seed(5);
  std::vector<Circle> circles;
  for (int i = 0; i < 600; ++i) {
    Circle c;
    c.cx = rng.Uniform(-6, 6);
    c.cy = rng.Uniform(-4, 4);
    // Mostly foot-bot sized, some wall pieces and big cylinders spanning many cells.
    c.r = i % 10 == 0 ? rng.Uniform(0.4, 2.0) : rng.Uniform(0.01, 0.1);
    circles.push_back(c);
  }
  UniformGrid grid;
  FileCircles(circles, &grid);
  EXPECT_GT(grid.Columns(), 20);  // a real grid, not one cell
  for (int q = 0; q < 2000; ++q) {
    const double radius = q % 2 ? 1.51 : 0.19;
    ExpectAllTouchingReportedOnce(grid, circles, rng.Uniform(-8, 8), rng.Uniform(-6, 6), radius);
    if (HasFatalFailure()) return;
  }
  // Beyond the grid's edges (queries clamped to the border cells).
  ExpectAllTouchingReportedOnce(grid, circles, 100, 100, 1.5);
}

TEST(UniformGrid, AFarOutlierGrowsTheCellsInsteadOfTheGrid) {
  std::vector<Circle> circles;
  for (int i = 0; i < 50; ++i) circles.push_back({0.3 * (i % 10), 0.3 * (i / 10), 0.085});
  circles.push_back({1e9, -1e9, 0.085});  // a robot flung a million km away by an exploded simulation
  UniformGrid grid;
  FileCircles(circles, &grid);
  EXPECT_LE(static_cast<double>(grid.Columns()) * grid.Rows(), 4096);
  ExpectAllTouchingReportedOnce(grid, circles, 1, 1, 1.51);
  ExpectAllTouchingReportedOnce(grid, circles, 1e9, -1e9, 0.19);
}

TEST(UniformGrid, HugeSpansAndNonFiniteQueriesAreHarmless) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Circle> circles = {{0, 0, 0.1}, {1.7e308, 0, 0.1}};
  UniformGrid grid;
  FileCircles(circles, &grid);
  EXPECT_LE(grid.Columns() * grid.Rows(), 4096);
  EXPECT_EQ(Query(grid, 0, 0, 0.5).count(0), 1u);
  circles.push_back({-1.7e308, 0, 0.1});
  FileCircles(circles, &grid);  // a span past the double range: one cell
  EXPECT_EQ(grid.Columns() * grid.Rows(), 1);
  EXPECT_EQ(Query(grid, 0, 0, 0.5).count(0), 1u);
  Query(grid, nan, nan, 0.5);  // no crash, no endless loop
  UniformGrid empty;
  FileCircles({}, &empty);
  EXPECT_TRUE(Query(empty, 0, 0, 1).empty());
}

// Used to be a heap overflow: NaN (a robot set_pose'd to 0/0) cast to INT_MIN as a cell.
TEST(UniformGrid, AnyDoubleLandsInAValidCell) {
  UniformGrid g;
  g.CoverBox(Vec2(-5, -5), Vec2(5, 5), 1.0, 1000);
  for (double v : {std::nan(""), 1e300, -1e300, HUGE_VAL, -HUGE_VAL, 0.0, 4.99, -5.0}) {
    EXPECT_GE(g.Column(v), 0) << v;
    EXPECT_LT(g.Column(v), g.Columns()) << v;
    EXPECT_GE(g.Row(v), 0) << v;
    EXPECT_LT(g.Row(v), g.Rows()) << v;
  }
}

// Found by fuzz_argos: an arena of 1e46 m over half-metre cells cast ~1e46 to int (UB)
// before the cell grew; an infinite box used to grow the cell forever.
TEST(UniformGrid, AHugeOrInfiniteBoxGetsAGridWithinItsCellBudget) {
  UniformGrid g;
  g.CoverBox(Vec2(-4.9e45, -1), Vec2(4.9e45, 1), 0.5, 1000);
  EXPECT_GE(g.Columns(), 1);
  EXPECT_LE(static_cast<size_t>(g.Columns()) * g.Rows(), 1000u);
  EXPECT_GE(g.CellSize(), 4.9e45 * 2 / 1000);
  g.CoverBox(Vec2(-HUGE_VAL, 0), Vec2(1, 1), 0.5, 1000);
  EXPECT_EQ(g.Columns(), 1);
  EXPECT_EQ(g.Rows(), 1);
  EXPECT_GE(g.Column(0.3), 0);
  EXPECT_LT(g.Column(0.3), 1);
}

TEST(UniformGrid, PointsInABoxMatchBruteForceInAscendingOrderPerCell) {
  Rng rng;
  rng.Seed(11);
  std::vector<Vec2> points;
  for (int i = 0; i < 500; ++i) points.emplace_back(rng.Uniform(-12, 12), rng.Uniform(-12, 12));  // some outside
  UniformGrid grid;
  grid.CoverBox(Vec2(-10, -10), Vec2(10, 10), 1.3, 4 * points.size() + 64);
  grid.FilePoints(static_cast<int>(points.size()), [&](int i) { return points[i]; });
  for (int q = 0; q < 500; ++q) {
    const Vec2 c(rng.Uniform(-11, 11), rng.Uniform(-11, 11));
    const double h = rng.Uniform(0.1, 3);
    std::vector<int> seen;
    grid.ForEachInBox(c.x() - h, c.y() - h, c.x() + h, c.y() + h, [&](int i) { seen.push_back(i); });
    std::vector<int> sorted = seen;
    std::sort(sorted.begin(), sorted.end());
    ASSERT_TRUE(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) << "a point came twice";
    for (size_t i = 0; i < points.size(); ++i) {
      const Vec2 d = (points[i] - c).cwiseAbs();
      if (d.x() <= h && d.y() <= h)
        ASSERT_TRUE(std::binary_search(sorted.begin(), sorted.end(), static_cast<int>(i)))
            << "point " << i << " missed";
    }
    const bool any = grid.AnyInBox(c.x() - h, c.y() - h, c.x() + h, c.y() + h, [](int) { return true; });
    EXPECT_EQ(any, !seen.empty());
  }
  // Within one cell, points come in ascending order.
  for (int row = 0; row < grid.Rows(); ++row)
    for (int col = 0; col < grid.Columns(); ++col) {
      const UniformGrid::Items items = grid.RowItems(row, col, col);
      EXPECT_TRUE(std::is_sorted(items.begin(), items.end()));
    }
}

TEST(BucketSort, IsStableAndReportsEachBucketsRange) {
  const std::vector<int> key = {3, 0, 2, 3, 0, 1, 3, 2, 0, 0};
  std::vector<int> start(5);
  std::vector<int> out(key.size(), -1);
  const int total = BucketSort(
      static_cast<int>(key.size()), &start, [&](int i, auto&& file) { file(key[i]); },
      [&](int slot, int i) { out[slot] = i; });
  EXPECT_EQ(total, 10);
  EXPECT_EQ(out, (std::vector<int>{1, 4, 8, 9, 5, 2, 7, 0, 3, 6}));  // by key, then by index
  EXPECT_EQ(start, (std::vector<int>{0, 4, 5, 7, 10}));
}

TEST(BucketSort, FilesAnItemInSeveralBucketsInOrder) {
  // Item i in buckets i and i + 1 (a box over two cells).
  std::vector<int> start(5);
  std::vector<int> out(6, -1);
  const int total = BucketSort(
      3, &start, [&](int i, auto&& file) { file(i), file(i + 1); }, [&](int slot, int i) { out[slot] = i; });
  EXPECT_EQ(total, 6);
  EXPECT_EQ(out, (std::vector<int>{0, 0, 1, 1, 2, 2}));
  EXPECT_EQ(start, (std::vector<int>{0, 1, 3, 5, 6}));
}

TEST(SegmentEntry, CircleHitsMissesAndStartsInside) {
  // From (0, 0) to (10, 0) into a unit circle at (5, 0): enters at x = 4, fraction 0.4.
  EXPECT_DOUBLE_EQ(CircleEntry(Vec2(0, 0), Vec2(10, 0), Vec2(5, 0), 1), 0.4);
  // Grazing 0.6 off the axis: enters where x = 5 - 0.8, fraction 0.42.
  EXPECT_NEAR(CircleEntry(Vec2(0, 0.6), Vec2(10, 0.6), Vec2(5, 0), 1), 0.42, 1e-12);
  EXPECT_EQ(CircleEntry(Vec2(0, 2), Vec2(10, 2), Vec2(5, 0), 1), 2);  // passes by
  EXPECT_EQ(CircleEntry(Vec2(0, 0), Vec2(3, 0), Vec2(5, 0), 1), 2);   // stops short
  EXPECT_EQ(CircleEntry(Vec2(5, 0), Vec2(10, 0), Vec2(5, 0), 1), 2);  // starts inside
  EXPECT_EQ(CircleEntry(Vec2(1, 1), Vec2(1, 1), Vec2(5, 0), 1), 2);   // no length
}

TEST(SegmentEntry, BoxHitsMissesAndTurns) {
  const Vec2 upright(1, 0);
  // A 2 × 1 box at (5, 0): entered at x = 4 from the left, fraction 0.4.
  EXPECT_DOUBLE_EQ(BoxEntry(Vec2(0, 0), Vec2(10, 0), Vec2(5, 0), upright, 1, 0.5), 0.4);
  // From below: entered at y = -0.5 of a segment from y = -2.5 to 1.5, fraction 0.5.
  EXPECT_DOUBLE_EQ(BoxEntry(Vec2(5, -2.5), Vec2(5, 1.5), Vec2(5, 0), upright, 1, 0.5), 0.5);
  EXPECT_EQ(BoxEntry(Vec2(0, 1), Vec2(10, 1), Vec2(5, 0), upright, 1, 0.5), 2);  // passes above
  EXPECT_EQ(BoxEntry(Vec2(5, 0), Vec2(10, 0), Vec2(5, 0), upright, 1, 0.5), 2);  // starts inside
  // Turned 90°: the long side along y, so the segment meets x = 4.5 at fraction 0.45.
  EXPECT_NEAR(BoxEntry(Vec2(0, 0), Vec2(10, 0), Vec2(5, 0), Vec2(0, 1), 1, 0.5), 0.45, 1e-12);
}

}  // namespace
}  // namespace essaim
