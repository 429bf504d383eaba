// ARGoS's small math helpers (argos3/core/utility/math/general.h).
#pragma once
#include <argos3/core/utility/datatypes/datatypes.h>

#include <cmath>

namespace argos {
const Real ARGOS_PI = 3.14159265358979323846264338327950288;

// As ARGoS's: compared with T(0), so Abs(CRadians) and Abs(CDegrees) work too.
template <typename T>
T Abs(const T& t_value) {
  if (t_value > T(0)) return t_value;
  if (t_value < T(0)) return -t_value;
  return T(0);
}
template <typename T>
T Min(const T& a, const T& b) {
  return a < b ? a : b;
}
template <typename T>
T Max(const T& a, const T& b) {
  return a > b ? a : b;
}
template <typename T>
T Square(const T& t_value) {
  return t_value * t_value;
}
}  // namespace argos
