// ARGoS's CVector3 (argos3/core/utility/math/vector3.h).
#pragma once
#include <argos3/core/utility/math/angles.h>
#include <argos3/core/utility/math/general.h>
#include <argos3/core/utility/math/vector2.h>
#include <argos3/core/utility/string_utilities.h>

#include <cmath>
#include <istream>
#include <ostream>

namespace argos {

class CQuaternion;

class CVector3 {
 public:
  CVector3() = default;
  CVector3(Real f_x, Real f_y, Real f_z) : m_fX(f_x), m_fY(f_y), m_fZ(f_z) {}
  Real GetX() const { return m_fX; }
  Real GetY() const { return m_fY; }
  Real GetZ() const { return m_fZ; }
  void SetX(Real f) { m_fX = f; }
  void SetY(Real f) { m_fY = f; }
  void SetZ(Real f) { m_fZ = f; }
  void Set(Real f_x, Real f_y, Real f_z) { m_fX = f_x, m_fY = f_y, m_fZ = f_z; }
  Real SquareLength() const { return m_fX * m_fX + m_fY * m_fY + m_fZ * m_fZ; }
  Real Length() const { return std::sqrt(SquareLength()); }
  CVector3& Normalize() { return *this /= Length(); }
  /// Rotated by `c_quaternion` (defined in quaternion.h).
  CVector3& Rotate(const CQuaternion& c_quaternion);
  CVector3& RotateZ(const CRadians& c_angle) {
    const Real s = Sin(c_angle), c = Cos(c_angle);
    return Set(m_fX * c - m_fY * s, m_fX * s + m_fY * c, m_fZ), *this;
  }
  Real DotProduct(const CVector3& c) const { return m_fX * c.m_fX + m_fY * c.m_fY + m_fZ * c.m_fZ; }
  CVector3 CrossProduct(const CVector3& c) const {
    return CVector3(m_fY * c.m_fZ - m_fZ * c.m_fY, m_fZ * c.m_fX - m_fX * c.m_fZ, m_fX * c.m_fY - m_fY * c.m_fX);
  }
  CVector2 ProjectOntoXY() const { return CVector2(m_fX, m_fY); }
  CVector3& operator+=(const CVector3& c) { return m_fX += c.m_fX, m_fY += c.m_fY, m_fZ += c.m_fZ, *this; }
  CVector3& operator-=(const CVector3& c) { return m_fX -= c.m_fX, m_fY -= c.m_fY, m_fZ -= c.m_fZ, *this; }
  CVector3& operator*=(Real f) { return m_fX *= f, m_fY *= f, m_fZ *= f, *this; }
  CVector3& operator/=(Real f) { return m_fX /= f, m_fY /= f, m_fZ /= f, *this; }
  CVector3 operator+(const CVector3& c) const { return CVector3(m_fX + c.m_fX, m_fY + c.m_fY, m_fZ + c.m_fZ); }
  CVector3 operator-(const CVector3& c) const { return CVector3(m_fX - c.m_fX, m_fY - c.m_fY, m_fZ - c.m_fZ); }
  CVector3 operator-() const { return CVector3(-m_fX, -m_fY, -m_fZ); }
  CVector3 operator*(Real f) const { return CVector3(m_fX * f, m_fY * f, m_fZ * f); }
  friend CVector3 operator*(Real f, const CVector3& c) { return c * f; }
  CVector3 operator/(Real f) const { return CVector3(m_fX / f, m_fY / f, m_fZ / f); }
  bool operator==(const CVector3& c) const { return m_fX == c.m_fX && m_fY == c.m_fY && m_fZ == c.m_fZ; }
  bool operator!=(const CVector3& c) const { return !(*this == c); }
  friend std::ostream& operator<<(std::ostream& os, const CVector3& c) {
    return os << c.m_fX << "," << c.m_fY << "," << c.m_fZ;
  }
  /// "x,y,z", as in the XML.
  friend std::istream& operator>>(std::istream& is, CVector3& c) {
    char comma1 = 0, comma2 = 0;
    is >> c.m_fX >> comma1 >> c.m_fY >> comma2 >> c.m_fZ;
    if (comma1 != ',' || comma2 != ',') is.setstate(std::ios::failbit);
    return is;
  }

  static const CVector3 ZERO, X, Y, Z;

 private:
  Real m_fX = 0, m_fY = 0, m_fZ = 0;
};

inline Real Distance(const CVector3& a, const CVector3& b) { return (a - b).Length(); }
inline Real SquareDistance(const CVector3& a, const CVector3& b) { return (a - b).SquareLength(); }

}  // namespace argos
