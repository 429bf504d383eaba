// ARGoS's angles (argos3/core/utility/math/angles.h): CRadians and CDegrees.
#pragma once
#include <argos3/core/utility/datatypes/datatypes.h>
#include <argos3/core/utility/math/general.h>
#include <argos3/core/utility/math/range.h>

#include <cmath>
#include <istream>
#include <ostream>

namespace argos {

template <typename T>
class CRange;

class CRadians {
 public:
  CRadians() = default;
  explicit CRadians(Real f_value) : m_fValue(f_value) {}
  Real GetValue() const { return m_fValue; }
  Real GetAbsoluteValue() const { return std::fabs(m_fValue); }
  void SetValue(Real f_value) { m_fValue = f_value; }
  CRadians& FromValueInDegrees(Real f_value) {
    m_fValue = f_value * ARGOS_PI / 180.0;
    return *this;
  }
  /// Into [-pi, pi].
  CRadians& SignedNormalize() {
    m_fValue = std::remainder(m_fValue, 2 * ARGOS_PI);
    return *this;
  }
  /// Into [0, 2pi).
  CRadians& UnsignedNormalize() {
    m_fValue = std::fmod(m_fValue, 2 * ARGOS_PI);
    if (m_fValue < 0) m_fValue += 2 * ARGOS_PI;
    return *this;
  }
  CRadians operator-() const { return CRadians(-m_fValue); }
  CRadians& operator+=(const CRadians& c) { return m_fValue += c.m_fValue, *this; }
  CRadians& operator-=(const CRadians& c) { return m_fValue -= c.m_fValue, *this; }
  CRadians& operator*=(Real f) { return m_fValue *= f, *this; }
  CRadians& operator/=(Real f) { return m_fValue /= f, *this; }
  CRadians operator+(const CRadians& c) const { return CRadians(m_fValue + c.m_fValue); }
  CRadians operator-(const CRadians& c) const { return CRadians(m_fValue - c.m_fValue); }
  CRadians operator*(Real f) const { return CRadians(m_fValue * f); }
  friend CRadians operator*(Real f, const CRadians& c) { return CRadians(f * c.m_fValue); }
  CRadians operator/(Real f) const { return CRadians(m_fValue / f); }
  Real operator/(const CRadians& c) const { return m_fValue / c.m_fValue; }
  bool operator<(const CRadians& c) const { return m_fValue < c.m_fValue; }
  bool operator<=(const CRadians& c) const { return m_fValue <= c.m_fValue; }
  bool operator>(const CRadians& c) const { return m_fValue > c.m_fValue; }
  bool operator>=(const CRadians& c) const { return m_fValue >= c.m_fValue; }
  bool operator==(const CRadians& c) const { return m_fValue == c.m_fValue; }
  bool operator!=(const CRadians& c) const { return m_fValue != c.m_fValue; }
  friend std::ostream& operator<<(std::ostream& os, const CRadians& c) {
    return os << "CRadians(" << c.m_fValue << " -> " << c.m_fValue * 180.0 / ARGOS_PI << " degrees)";
  }

  static const CRadians PI, TWO_PI, PI_OVER_TWO, PI_OVER_THREE, PI_OVER_FOUR, PI_OVER_SIX, ZERO;
  static const CRange<CRadians> SIGNED_RANGE, UNSIGNED_RANGE;

 private:
  Real m_fValue = 0;
};

class CDegrees {
 public:
  CDegrees() = default;
  explicit CDegrees(Real f_value) : m_fValue(f_value) {}
  Real GetValue() const { return m_fValue; }
  void SetValue(Real f_value) { m_fValue = f_value; }
  CDegrees& SignedNormalize() {
    m_fValue = std::remainder(m_fValue, 360.0);
    return *this;
  }
  CDegrees& UnsignedNormalize() {
    m_fValue = std::fmod(m_fValue, 360.0);
    if (m_fValue < 0) m_fValue += 360.0;
    return *this;
  }
  CDegrees operator-() const { return CDegrees(-m_fValue); }
  CDegrees& operator+=(const CDegrees& c) { return m_fValue += c.m_fValue, *this; }
  CDegrees& operator-=(const CDegrees& c) { return m_fValue -= c.m_fValue, *this; }
  CDegrees& operator*=(Real f) { return m_fValue *= f, *this; }
  CDegrees& operator/=(Real f) { return m_fValue /= f, *this; }
  CDegrees operator+(const CDegrees& c) const { return CDegrees(m_fValue + c.m_fValue); }
  CDegrees operator-(const CDegrees& c) const { return CDegrees(m_fValue - c.m_fValue); }
  CDegrees operator*(Real f) const { return CDegrees(m_fValue * f); }
  friend CDegrees operator*(Real f, const CDegrees& c) { return CDegrees(f * c.m_fValue); }
  CDegrees operator/(Real f) const { return CDegrees(m_fValue / f); }
  Real operator/(const CDegrees& c) const { return m_fValue / c.m_fValue; }
  bool operator<(const CDegrees& c) const { return m_fValue < c.m_fValue; }
  bool operator<=(const CDegrees& c) const { return m_fValue <= c.m_fValue; }
  bool operator>(const CDegrees& c) const { return m_fValue > c.m_fValue; }
  bool operator>=(const CDegrees& c) const { return m_fValue >= c.m_fValue; }
  bool operator==(const CDegrees& c) const { return m_fValue == c.m_fValue; }
  bool operator!=(const CDegrees& c) const { return m_fValue != c.m_fValue; }
  friend std::ostream& operator<<(std::ostream& os, const CDegrees& c) {
    return os << "CDegrees(" << c.m_fValue << ")";
  }
  friend std::istream& operator>>(std::istream& is, CDegrees& c) { return is >> c.m_fValue; }

 private:
  Real m_fValue = 0;
};

inline CRadians ToRadians(const CDegrees& c) { return CRadians(c.GetValue() * ARGOS_PI / 180.0); }
inline CDegrees ToDegrees(const CRadians& c) { return CDegrees(c.GetValue() * 180.0 / ARGOS_PI); }
inline Real Sin(const CRadians& c) { return std::sin(c.GetValue()); }
inline Real Cos(const CRadians& c) { return std::cos(c.GetValue()); }
inline Real Tan(const CRadians& c) { return std::tan(c.GetValue()); }
inline CRadians ASin(Real f) { return CRadians(std::asin(f)); }
inline CRadians ACos(Real f) { return CRadians(std::acos(f)); }
inline CRadians ATan2(Real y, Real x) { return CRadians(std::atan2(y, x)); }
inline CRadians NormalizedDifference(const CRadians& a, const CRadians& b) { return (a - b).SignedNormalize(); }

}  // namespace argos
