#include "model/placement.h"

#include <cmath>

namespace essaim {

namespace {
/// m: cells of about two foot-bot diameters, so a foot-bot's box covers one to four.
constexpr double kPlacementCell = 0.5;

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
}  // namespace

void PlacedFootprints::Cover(const Vec2& min, const Vec2& max) {
  min_ = min;
  max_ = max;
  Refile();
}

void PlacedFootprints::Add(const Footprint& f) {
  Vec2 lo, hi;
  BoundingBox(f, &lo, &hi);
  placed_.push_back(f);
  lo_.push_back(lo);
  hi_.push_back(hi);
  const size_t pending = placed_.size() - filed_;
  if (pending * pending > 256 + filed_) Refile();
}

void PlacedFootprints::Refile() {
  filed_ = placed_.size();
  grid_.CoverBox(min_, max_, kPlacementCell, 4 * filed_ + 4096);
  grid_.FileBoxes(
      static_cast<int>(filed_), [&](int i) { return lo_[i]; }, [&](int i) { return hi_[i]; });
}

int PlacedFootprints::FirstOverlap(const Footprint& f) const {
  Vec2 lo, hi;
  BoundingBox(f, &lo, &hi);
  int first = -1;
  auto consider = [&](int i) {
    if (first >= 0 && i >= first) return;
    if (hi.x() < lo_[i].x() || lo.x() > hi_[i].x() || hi.y() < lo_[i].y() || lo.y() > hi_[i].y()) return;
    if (FootprintsOverlap(f, placed_[i])) first = i;
  };
  grid_.ForEachInBox(lo.x(), lo.y(), hi.x(), hi.y(), consider);
  for (size_t i = filed_; i < placed_.size(); ++i) consider(static_cast<int>(i));
  return first;
}

bool PlacedFootprints::Collides(const Footprint& f) const {
  Vec2 lo, hi;
  BoundingBox(f, &lo, &hi);
  auto overlaps = [&](int i) {
    if (hi.x() < lo_[i].x() || lo.x() > hi_[i].x() || hi.y() < lo_[i].y() || lo.y() > hi_[i].y()) return false;
    return FootprintsOverlap(f, placed_[i]);
  };
  if (grid_.AnyInBox(lo.x(), lo.y(), hi.x(), hi.y(), overlaps)) return true;
  for (size_t i = filed_; i < placed_.size(); ++i)
    if (overlaps(static_cast<int>(i))) return true;
  return false;
}

}  // namespace essaim
