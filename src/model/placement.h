// The footprints placed so far in the arena, for the overlap test that explicit and
// generated (<distribute>) entities must pass. A uniform grid over the arena answers which
// footprints are near a new one; each footprint is filed in its cells as it is added, and
// the cells are made finer (all footprints filed anew) each time the count doubles, so
// placing n entities costs about n times the footprints near each, never n² or n·sqrt(n).
#pragma once
#include <vector>

#include "model/distribute.h"
#include "spatial/uniform_grid.h"

namespace essaim {

class PlacedFootprints {
 public:
  /// The box most footprints lie in (the arena); those outside it are still found.
  void Cover(const Vec2& min, const Vec2& max);
  void Add(const Footprint& f);
  /// True when `f` overlaps a placed footprint (FootprintsOverlap): the same answer as
  /// testing every one of them.
  bool Collides(const Footprint& f) const;
  /// The lowest index (in the order added) of a placed footprint that `f` overlaps, -1 if none.
  int FirstOverlap(const Footprint& f) const;
  size_t Size() const { return placed_.size(); }

 private:
  /// Cells sized for up to `capacity` footprints, every footprint filed in them anew.
  void Regrid(size_t capacity);
  /// Files footprint i in the cells its box covers.
  void File(int i);
  /// Calls f(i) for each footprint filed in a cell the box [lo, hi] covers (a footprint in
  /// several of them once per cell); stops and returns true when f returns true.
  template <class F>
  bool AnyFiledNear(const Vec2& lo, const Vec2& hi, F&& f) const;

  std::vector<Footprint> placed_;
  std::vector<Vec2> lo_, hi_;  // m, each footprint's bounding box, widened far beyond rounding
  Vec2 min_ = Vec2::Zero(), max_ = Vec2::Zero();
  /// The cells' geometry only (Column, Row): footprints arrive one at a time, and a
  /// counting-sorted grid would have to be filed whole for each.
  UniformGrid cells_;
  /// Per cell the newest entry filed there (-1: none); each entry names a footprint and the
  /// entry filed in that cell before it.
  struct Entry {
    int item, next;
  };
  std::vector<int> head_;
  std::vector<Entry> entries_;
  size_t capacity_ = 0;  // footprints the cells are sized for
};

}  // namespace essaim
