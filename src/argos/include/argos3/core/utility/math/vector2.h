// ARGoS's CVector2 (argos3/core/utility/math/vector2.h).
#pragma once
#include <argos3/core/utility/math/angles.h>
#include <argos3/core/utility/math/general.h>
#include <argos3/core/utility/string_utilities.h>

#include <cmath>
#include <istream>
#include <ostream>

namespace argos {

class CVector2 {
 public:
  CVector2() = default;
  CVector2(Real f_x, Real f_y) : m_fX(f_x), m_fY(f_y) {}
  /// From length and angle.
  CVector2(Real f_length, const CRadians& c_angle) : m_fX(f_length * Cos(c_angle)), m_fY(f_length * Sin(c_angle)) {}
  Real GetX() const { return m_fX; }
  Real GetY() const { return m_fY; }
  void SetX(Real f) { m_fX = f; }
  void SetY(Real f) { m_fY = f; }
  void Set(Real f_x, Real f_y) { m_fX = f_x, m_fY = f_y; }
  void FromPolarCoordinates(Real f_length, const CRadians& c_angle) { *this = CVector2(f_length, c_angle); }
  Real SquareLength() const { return m_fX * m_fX + m_fY * m_fY; }
  Real Length() const { return std::sqrt(SquareLength()); }
  CVector2& Normalize() { return *this /= Length(); }
  CVector2& Rotate(const CRadians& c_angle) {
    const Real s = Sin(c_angle), c = Cos(c_angle);
    return Set(m_fX * c - m_fY * s, m_fX * s + m_fY * c), *this;
  }
  CRadians Angle() const { return ATan2(m_fY, m_fX); }
  Real DotProduct(const CVector2& c) const { return m_fX * c.m_fX + m_fY * c.m_fY; }
  CVector2& Scale(Real f_x, Real f_y) { return m_fX *= f_x, m_fY *= f_y, *this; }
  CVector2& operator+=(const CVector2& c) { return m_fX += c.m_fX, m_fY += c.m_fY, *this; }
  CVector2& operator-=(const CVector2& c) { return m_fX -= c.m_fX, m_fY -= c.m_fY, *this; }
  CVector2& operator*=(Real f) { return m_fX *= f, m_fY *= f, *this; }
  CVector2& operator/=(Real f) { return m_fX /= f, m_fY /= f, *this; }
  CVector2 operator+(const CVector2& c) const { return CVector2(m_fX + c.m_fX, m_fY + c.m_fY); }
  CVector2 operator-(const CVector2& c) const { return CVector2(m_fX - c.m_fX, m_fY - c.m_fY); }
  CVector2 operator-() const { return CVector2(-m_fX, -m_fY); }
  CVector2 operator*(Real f) const { return CVector2(m_fX * f, m_fY * f); }
  friend CVector2 operator*(Real f, const CVector2& c) { return c * f; }
  CVector2 operator/(Real f) const { return CVector2(m_fX / f, m_fY / f); }
  bool operator==(const CVector2& c) const { return m_fX == c.m_fX && m_fY == c.m_fY; }
  bool operator!=(const CVector2& c) const { return !(*this == c); }
  friend std::ostream& operator<<(std::ostream& os, const CVector2& c) { return os << c.m_fX << "," << c.m_fY; }
  /// "x,y", as in the XML.
  friend std::istream& operator>>(std::istream& is, CVector2& c) {
    char comma = 0;
    is >> c.m_fX >> comma >> c.m_fY;
    if (comma != ',') is.setstate(std::ios::failbit);
    return is;
  }

  static const CVector2 ZERO, X, Y;

 private:
  Real m_fX = 0, m_fY = 0;
};

inline Real Distance(const CVector2& a, const CVector2& b) { return (a - b).Length(); }
inline Real SquareDistance(const CVector2& a, const CVector2& b) { return (a - b).SquareLength(); }

}  // namespace argos
