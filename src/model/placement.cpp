#include "model/placement.h"

#include <algorithm>
#include <cmath>

namespace essaim {

namespace {
/// m: cells of about two foot-bot diameters, so a foot-bot's box covers one to four.
constexpr double kPlacementCell = 0.5;
/// Footprints the first cells are sized for; the cells are made finer as the count doubles.
constexpr size_t kFirstCapacity = 1024;

/// The footprint's bounding box, widened by far more than the overlap tests' rounding, so
/// that footprints that overlap always have boxes that meet.
void BoundingBox(const Footprint& f, Vec2* lo, Vec2* hi) {
  Vec2 half(f.radius, f.radius);
  if (!f.is_circle) {
    const double c = std::abs(std::cos(f.yaw)), s = std::abs(std::sin(f.yaw));
    half = Vec2(c * f.half_x + s * f.half_y, s * f.half_x + c * f.half_y);
  }
  const Vec2 margin = (half + f.center.cwiseAbs()) * 1e-9 + Vec2(1e-9, 1e-9);
  *lo = f.center - half - margin;
  *hi = f.center + half + margin;
}

bool BoxesMeet(const Vec2& lo, const Vec2& hi, const Vec2& other_lo, const Vec2& other_hi) {
  return !(hi.x() < other_lo.x() || lo.x() > other_hi.x() || hi.y() < other_lo.y() || lo.y() > other_hi.y());
}
}  // namespace

void PlacedFootprints::Cover(const Vec2& min, const Vec2& max) {
  min_ = min;
  max_ = max;
  Regrid(std::max(capacity_, kFirstCapacity));
}

void PlacedFootprints::Regrid(size_t capacity) {
  capacity_ = capacity;
  // About four cells per footprint at most: a sparse arena gets coarser cells, not a huge grid.
  cells_.CoverBox(min_, max_, kPlacementCell, 4 * capacity + 4096);
  head_.assign(static_cast<size_t>(cells_.Columns()) * cells_.Rows(), -1);
  entries_.clear();
  for (size_t i = 0; i < placed_.size(); ++i) File(static_cast<int>(i));
}

void PlacedFootprints::File(int i) {
  const int col0 = cells_.Column(lo_[i].x()), col1 = cells_.Column(hi_[i].x());
  for (int row = cells_.Row(lo_[i].y()), row1 = cells_.Row(hi_[i].y()); row <= row1; ++row)
    for (int col = col0; col <= col1; ++col) {
      int& head = head_[static_cast<size_t>(row) * cells_.Columns() + col];
      entries_.push_back({i, head});
      head = static_cast<int>(entries_.size() - 1);
    }
}

void PlacedFootprints::Add(const Footprint& f) {
  Vec2 lo, hi;
  BoundingBox(f, &lo, &hi);
  placed_.push_back(f);
  lo_.push_back(lo);
  hi_.push_back(hi);
  if (placed_.size() > capacity_)
    Regrid(std::max(2 * capacity_, kFirstCapacity));  // files the new one too
  else
    File(static_cast<int>(placed_.size() - 1));
}

template <class F>
bool PlacedFootprints::AnyFiledNear(const Vec2& lo, const Vec2& hi, F&& f) const {
  const int col0 = cells_.Column(lo.x()), col1 = cells_.Column(hi.x());
  for (int row = cells_.Row(lo.y()), row1 = cells_.Row(hi.y()); row <= row1; ++row)
    for (int col = col0; col <= col1; ++col)
      for (int e = head_[static_cast<size_t>(row) * cells_.Columns() + col]; e >= 0; e = entries_[e].next)
        if (f(entries_[e].item)) return true;
  return false;
}

int PlacedFootprints::FirstOverlap(const Footprint& f) const {
  Vec2 lo, hi;
  BoundingBox(f, &lo, &hi);
  int first = -1;
  AnyFiledNear(lo, hi, [&](int i) {
    if ((first < 0 || i < first) && BoxesMeet(lo, hi, lo_[i], hi_[i]) && FootprintsOverlap(f, placed_[i])) first = i;
    return false;  // all of them: the lowest index wins
  });
  return first;
}

bool PlacedFootprints::Collides(const Footprint& f) const {
  Vec2 lo, hi;
  BoundingBox(f, &lo, &hi);
  return AnyFiledNear(lo, hi,
                      [&](int i) { return BoxesMeet(lo, hi, lo_[i], hi_[i]) && FootprintsOverlap(f, placed_[i]); });
}

}  // namespace essaim
