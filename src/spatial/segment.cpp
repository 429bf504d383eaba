#include "spatial/segment.h"

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

}  // namespace essaim
