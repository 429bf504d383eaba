// Where a segment enters a circle or a box: Box2D's own ray casts redone in double, so
// media can decide what one Box2D ray would without walking Box2D's tree per ray.
#pragma once
#include <cmath>

#include "core/math.h"

namespace essaim {

/// Segment fraction at which from -> to enters a circle (Box2D's circle ray cast); 2 when
/// it misses, also when it starts inside. Inline: the media stage calls it for every
/// (pair, body) in range, about a tenth of a 300-robot foraging run as a call.
inline double CircleEntry(const Vec2& from, const Vec2& to, const Vec2& center, double radius) {
  // b2CircleShape::RayCast: the smaller root of |from + t(to - from) - center| = radius, if in [0, 1].
  const Vec2 offset = center - from;
  const double offset_power = offset.squaredNorm() - radius * radius;
  if (offset_power < 0) return 2;
  const Vec2 d = to - from;
  const double dd = d.squaredNorm();
  const double along = offset.dot(d);
  const double disc = along * along - dd * offset_power;
  if (disc < 0 || dd <= 0) return 2;
  const double t = (along - std::sqrt(disc)) / dd;
  return t >= 0 && t <= 1 ? t : 2;
}

/// Same for a box of half sizes (hx, hy), yaw (cos, sin) = cs (Box2D's polygon ray cast).
double BoxEntry(const Vec2& from, const Vec2& to, const Vec2& center, const Vec2& cs, double hx, double hy);

/// The part of segment from -> to that lies inside a circle: its fractions [*t0, *t1]
/// within [0, 1] (a segment starting or ending inside included); false when there is none.
bool CircleSpan(const Vec2& from, const Vec2& to, const Vec2& center, double radius, double* t0, double* t1);
/// Same for a box of half sizes (hx, hy), yaw (cos, sin) = cs.
bool BoxSpan(const Vec2& from, const Vec2& to, const Vec2& center, const Vec2& cs, double hx, double hy, double* t0,
             double* t1);

}  // namespace essaim
