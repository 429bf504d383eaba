// Blocker probes for the range-and-bearing occlusion scan (rab_routing.cpp): per
// direction sector around a device, one nearby body likely to hide every pair in that
// sector. A pair tests its sector's blocker first with the exact test, then scans as
// before; the guess decides nothing (a wrong one costs one test), so rounding is moot here.
#pragma once
#include <algorithm>
#include <cmath>

#include "devices/rab_routing.h"

namespace essaim {
namespace rab_blockers {

/// Pseudo-angle of direction (x, y) in [0, 4]: quadrant + |y| or |x| over |x| + |y|,
/// increasing counterclockwise like the angle (no trig). Only steers probes: rounding is moot.
inline double PseudoAngle(double x, double y) {
  const double ax = std::abs(x), ay = std::abs(y);
  const bool odd = (x < 0) != (y < 0);  // quadrants 1 and 3 measure from the y axis
  return 2 * (y < 0) + odd + (odd ? ax : ay) / (ax + ay);
}

constexpr int kSectors = rab::kProbeSectors;
inline int SectorOf(double pseudo_angle) { return static_cast<int>(pseudo_angle * (kSectors / 4)) & (kSectors - 1); }

/// Per direction sector, the first of the first n_occ occluders (nearest first, to a
/// bucket) whose circle spans the sector's middle direction as seen from the device, its
/// half-width estimated from r/|s|. Pairs of that sector test it first: in a crowd it
/// hides most of them at once.
inline void FindBlockers(RabScratch& scratch, int n_occ) {
  constexpr double r = footbot::kRadius;
  std::fill(scratch.sector_blocker.begin(), scratch.sector_blocker.end(), -1);
  for (int i = 0; i < n_occ; ++i) {
    const RabOccluder& o = scratch.occluders[i];
    if (std::isinf(o.tangent2)) continue;  // only its gripper disc may hide: no blocker
    const double l1 = std::abs(o.offset_x) + std::abs(o.offset_y);
    // Half-width asin(r/|s|) >= r/|s| rad, times the pseudo-angle's slope |s|²/l1² here:
    // at most 1 (|s| >= r, l1 >= |s|), so k0 >= 0 and at most kSectors / 2 + 1 sectors.
    const double w = r * std::sqrt(o.tangent2 + r * r) / (l1 * l1);
    const double p = PseudoAngle(o.offset_x, o.offset_y);
    const int k0 = static_cast<int>((p - w) * (kSectors / 4) + (kSectors + 0.5));  // sectors whose middle
    const int k1 = static_cast<int>((p + w) * (kSectors / 4) + (kSectors - 0.5));  // is in [p - w, p + w]
    for (int k = k0; k <= k1; ++k) {
      int& blocker = scratch.sector_blocker[k & (kSectors - 1)];
      if (blocker < 0) blocker = i;
    }
  }
}

}  // namespace rab_blockers
}  // namespace essaim
