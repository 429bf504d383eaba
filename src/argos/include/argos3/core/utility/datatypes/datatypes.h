// ARGoS's fixed-size number types (argos3/core/utility/datatypes/datatypes.h), for loop
// functions built against essaim (docs/loop-functions.md, "C++ loop functions").
#pragma once
#include <cstdint>

namespace argos {
typedef double Real;
typedef int8_t SInt8;
typedef uint8_t UInt8;
typedef int16_t SInt16;
typedef uint16_t UInt16;
typedef int32_t SInt32;
typedef uint32_t UInt32;
typedef int64_t SInt64;
typedef uint64_t UInt64;
}  // namespace argos
