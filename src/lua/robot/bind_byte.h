// C++'s static_cast<uint8_t>(double) as ARGoS's bindings use it on x86: truncate, then
// wrap modulo 256 (300 -> 44, -1 -> 255). Non-finite or huge values give 0.
#pragma once
#include <cmath>
#include <cstdint>

namespace essaim {

inline uint8_t LuaNumberToByte(double v) {
  if (!std::isfinite(v) || std::fabs(v) >= 9.2e18) return 0;
  return static_cast<uint8_t>(static_cast<int64_t>(std::trunc(v)));
}

}  // namespace essaim
