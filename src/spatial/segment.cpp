#include "spatial/segment.h"

#include <algorithm>

namespace essaim {

double BoxEntry(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& cs, double hx, double hy) {
  // b2PolygonShape::RayCast in the box frame: clip [0, 1] by the four edges; a hit needs
  // an entering edge (a segment starting inside reports nothing).
  const Vec2 ra = a - c, rb = b - c;
  const Vec2 p(cs.x() * ra.x() + cs.y() * ra.y(), -cs.y() * ra.x() + cs.x() * ra.y());
  const Vec2 q(cs.x() * rb.x() + cs.y() * rb.y(), -cs.y() * rb.x() + cs.x() * rb.y());
  const Vec2 d = q - p;
  double lower = 0, upper = 1;
  bool entered = false;
  const double h[2] = {hx, hy};
  for (int k = 0; k < 2; ++k) {
    for (double side : {-1.0, 1.0}) {
      const double num = h[k] - side * p[k];  // edge with outward normal side·e_k
      const double den = side * d[k];
      if (den == 0) {
        if (num < 0) return 2;
      } else if (den < 0 && num < lower * den) {
        lower = num / den;
        entered = true;
      } else if (den > 0 && num < upper * den) {
        upper = num / den;
      }
      if (upper < lower) return 2;
    }
  }
  return entered ? lower : 2;
}

bool CircleSpan(const Vec2& a, const Vec2& b, const Vec2& c, double r, double* t0, double* t1) {
  // |a + t(b - a) - c| <= r between the two roots of the quadratic in t.
  const Vec2 offset = c - a, d = b - a;
  const double dd = d.squaredNorm();
  const double power = offset.squaredNorm() - r * r;
  if (!(dd > 0)) {  // a point: inside or not
    *t0 = 0, *t1 = 1;
    return power <= 0;
  }
  const double along = offset.dot(d);
  const double disc = along * along - dd * power;
  if (disc < 0) return false;
  const double root = std::sqrt(disc);
  *t0 = std::max(0.0, (along - root) / dd);
  *t1 = std::min(1.0, (along + root) / dd);
  return *t0 <= *t1;
}

bool BoxSpan(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& cs, double hx, double hy, double* t0,
             double* t1) {
  // Liang-Barsky in the box frame: [0, 1] clipped by the four edges.
  const Vec2 ra = a - c, rb = b - c;
  const Vec2 p(cs.x() * ra.x() + cs.y() * ra.y(), -cs.y() * ra.x() + cs.x() * ra.y());
  const Vec2 q(cs.x() * rb.x() + cs.y() * rb.y(), -cs.y() * rb.x() + cs.x() * rb.y());
  const Vec2 d = q - p;
  double lower = 0, upper = 1;
  const double h[2] = {hx, hy};
  for (int k = 0; k < 2; ++k)
    for (double side : {-1.0, 1.0}) {
      const double num = h[k] - side * p[k];  // >= 0 where inside this edge
      const double den = side * d[k];
      if (den == 0) {
        if (num < 0) return false;
      } else if (den < 0) {
        lower = std::max(lower, num / den);
      } else {
        upper = std::min(upper, num / den);
      }
    }
  *t0 = lower, *t1 = upper;
  return lower <= upper;
}

}  // namespace essaim
