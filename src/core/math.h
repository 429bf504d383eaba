// Math vocabulary shared by every layer: Eigen vectors, angle helpers, poses.
#pragma once
#include <Eigen/Core>
#include <cmath>

namespace essaim {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;

/// Wraps an angle into [-pi, pi] (ARGoS "signed normalize").
inline double WrapSigned(double a) {
  if (a > kPi || a < -kPi) {
    a = std::fmod(a, kTwoPi);
    if (a > kPi)
      a -= kTwoPi;
    else if (a < -kPi)
      a += kTwoPi;
  }
  return a;
}

/// Wraps an angle into [0, 2pi) (ARGoS "unsigned normalize").
inline double WrapUnsigned(double a) {
  a = std::fmod(a, kTwoPi);
  if (a < 0) a += kTwoPi;
  return a;
}

inline double DegToRad(double d) { return d * kPi / 180.0; }

/// Planar pose: position (m) and yaw (rad, CCW from +X).
struct Pose2 {
  double x = 0, y = 0, yaw = 0;
};

/// RGBA colour, 0..255 per channel, as ARGoS's CColor.
struct Color {
  unsigned char r = 0, g = 0, b = 0, a = 255;
  bool operator==(const Color& o) const { return r == o.r && g == o.g && b == o.b && a == o.a; }
  bool operator!=(const Color& o) const { return !(*this == o); }
  bool IsBlack() const { return r == 0 && g == 0 && b == 0; }
};

}  // namespace essaim
