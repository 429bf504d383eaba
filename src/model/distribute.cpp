#include "model/distribute.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace essaim {

bool Generator::Next(Rng& rng, int k, Vec3* out) const {
  switch (kind) {
    case Kind::Uniform:
      for (int i = 0; i < 3; ++i) (*out)[i] = rng.Uniform(a[i], b[i]);
      return true;
    case Kind::Gaussian:
      for (int i = 0; i < 3; ++i) (*out)[i] = rng.Gaussian(b[i], a[i]);
      return true;
    case Kind::Constant:
      *out = a;
      return true;
    case Kind::Grid: {
      const int nx = layout[0], ny = layout[1], nz = layout[2];
      if (k >= nx * ny * nz) return false;
      (*out)[0] = a[0] + (nx - 1) * b[0] / 2 - (k % nx) * b[0];
      (*out)[1] = a[1] + (ny - 1) * b[1] / 2 - ((k / nx) % ny) * b[1];
      (*out)[2] = a[2] + (nz - 1) * b[2] / 2 - (k / (nx * ny)) * b[2];
      return true;
    }
  }
  return false;
}

double RoundSignificant6(double v) {
  char buf[32];
  if (!std::isfinite(v)) {  // "nan" or "inf" and back, as ARGoS's text goes
    std::snprintf(buf, sizeof buf, "%g", v);
    return std::strtod(buf, nullptr);
  }
  // The same digits as "%g" and the same double as strtod (all four round correctly), at a
  // third of the cost: every placement attempt rounds six values.
  const std::to_chars_result text = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 6);
  double out = v;
  std::from_chars(buf, text.ptr, out);
  return out;
}

namespace {
bool CircleRect(const Footprint& c, const Footprint& r) {
  // Circle centre in the rectangle's frame, closest point by clamping.
  Vec2 d = c.center - r.center;
  double cs = std::cos(-r.yaw), sn = std::sin(-r.yaw);
  Vec2 local(cs * d.x() - sn * d.y(), sn * d.x() + cs * d.y());
  Vec2 closest(std::clamp(local.x(), -r.half_x, r.half_x), std::clamp(local.y(), -r.half_y, r.half_y));
  return (local - closest).squaredNorm() < c.radius * c.radius;
}

void Corners(const Footprint& r, Vec2 out[4]) {
  double cs = std::cos(r.yaw), sn = std::sin(r.yaw);
  const double sx[4] = {1, -1, -1, 1}, sy[4] = {1, 1, -1, -1};
  for (int i = 0; i < 4; ++i) {
    double lx = sx[i] * r.half_x, ly = sy[i] * r.half_y;
    out[i] = r.center + Vec2(cs * lx - sn * ly, sn * lx + cs * ly);
  }
}

bool RectRect(const Footprint& a, const Footprint& b) {
  // Separating axis test on the four edge normals.
  Vec2 ca[4], cb[4];
  Corners(a, ca);
  Corners(b, cb);
  const double yaws[2] = {a.yaw, b.yaw};
  for (double yaw : yaws) {
    for (int k = 0; k < 2; ++k) {
      Vec2 axis = k == 0 ? Vec2(std::cos(yaw), std::sin(yaw)) : Vec2(-std::sin(yaw), std::cos(yaw));
      double amin = 1e300, amax = -1e300, bmin = 1e300, bmax = -1e300;
      for (int i = 0; i < 4; ++i) {
        double pa = axis.dot(ca[i]), pb = axis.dot(cb[i]);
        amin = std::min(amin, pa), amax = std::max(amax, pa);
        bmin = std::min(bmin, pb), bmax = std::max(bmax, pb);
      }
      if (amax <= bmin || bmax <= amin) return false;
    }
  }
  return true;
}
}  // namespace

Footprint ObstacleFootprint(const ObstacleDef& o) {
  Footprint f;
  f.center = {o.pose.x, o.pose.y};
  if (o.kind == ShapeKind::Cylinder) {
    f.radius = o.radius;
  } else {
    f.is_circle = false;
    f.half_x = o.size_x / 2, f.half_y = o.size_y / 2, f.yaw = o.pose.yaw;
  }
  return f;
}

bool FootprintsOverlap(const Footprint& a, const Footprint& b) {
  if (a.is_circle && b.is_circle) {
    double r = a.radius + b.radius;
    return (a.center - b.center).squaredNorm() < r * r;
  }
  if (a.is_circle) return CircleRect(a, b);
  if (b.is_circle) return CircleRect(b, a);
  return RectRect(a, b);
}

}  // namespace essaim
