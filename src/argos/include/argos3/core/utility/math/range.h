// ARGoS's CRange<T> (argos3/core/utility/math/range.h): an interval [min, max].
#pragma once
#include <argos3/core/utility/configuration/argos_exception.h>
#include <argos3/core/utility/datatypes/datatypes.h>
#include <argos3/core/utility/string_utilities.h>

#include <istream>
#include <ostream>

namespace argos {

template <typename T>
class CRange {
 public:
  CRange() = default;
  CRange(const T& t_min, const T& t_max) : m_tMin(t_min), m_tMax(t_max) {
    if (t_min > t_max) THROW_ARGOSEXCEPTION("CRange: min " << t_min << " is greater than max " << t_max);
  }
  const T& GetMin() const { return m_tMin; }
  const T& GetMax() const { return m_tMax; }
  T GetSpan() const { return m_tMax - m_tMin; }
  void SetMin(const T& t) { m_tMin = t; }
  void SetMax(const T& t) { m_tMax = t; }
  void Set(const T& t_min, const T& t_max) { m_tMin = t_min, m_tMax = t_max; }
  bool WithinMinBoundIncludedMaxBoundIncluded(const T& t) const { return t >= m_tMin && t <= m_tMax; }
  bool WithinMinBoundIncludedMaxBoundExcluded(const T& t) const { return t >= m_tMin && t < m_tMax; }
  bool WithinMinBoundExcludedMaxBoundIncluded(const T& t) const { return t > m_tMin && t <= m_tMax; }
  bool WithinMinBoundExcludedMaxBoundExcluded(const T& t) const { return t > m_tMin && t < m_tMax; }
  void TruncValue(T& t) const {
    if (t > m_tMax) t = m_tMax;
    if (t < m_tMin) t = m_tMin;
  }
  friend std::ostream& operator<<(std::ostream& os, const CRange& c) { return os << c.m_tMin << ":" << c.m_tMax; }
  /// "min:max", as ARGoS reads a range from XML.
  friend std::istream& operator>>(std::istream& is, CRange& c) {
    char colon = 0;
    T t_min, t_max;
    is >> t_min >> colon >> t_max;
    if (colon != ':') is.setstate(std::ios::failbit);
    c.Set(t_min, t_max);
    return is;
  }

 private:
  T m_tMin{};
  T m_tMax{};
};

}  // namespace argos
