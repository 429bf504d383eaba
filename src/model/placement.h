// The footprints placed so far in the arena, for the overlap test that explicit and
// generated (<distribute>) entities must pass. A uniform grid answers which footprints
// are near a new one, so placing n entities costs about n·sqrt(n), not n².
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
  /// Files every footprint in the grid anew.
  void Refile();

  std::vector<Footprint> placed_;
  std::vector<Vec2> lo_, hi_;  // m, each footprint's bounding box, widened far beyond rounding
  Vec2 min_ = Vec2::Zero(), max_ = Vec2::Zero();
  UniformGrid grid_;
  /// placed_[0, filed_) are in the grid; the few after them are tested one by one until
  /// there are more than about sqrt(filed_), when the grid is filed anew.
  size_t filed_ = 0;
};

}  // namespace essaim
