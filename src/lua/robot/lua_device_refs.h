// Per-robot handles to its Lua device tables; no Lua header, so the sim layer can hold it.
#pragma once
#include "model/device_table.h"

namespace essaim {

/// The keys readings are stored under. Each state keeps them as Lua strings in its
/// registry, referenced at the first use of each (LuaKeyRefs): a refill pushes a key with
/// lua_rawgeti, where lua_setfield / lua_pushstring of a C string looks it up in Lua's
/// string cache, a strcmp and two cold cache lines (the cache's row, the string) per field.
enum class LuaKey : int {
  Value = 1,
  Position,
  Orientation,
  VelocityLeft,
  VelocityRight,
  DistanceLeft,
  DistanceRight,
  AvailableCharge,
  TimeLeft,
  Rotation,
  Range,
  HorizontalBearing,
  VerticalBearing,
  Data,
  Distance,
  Angle,
  Color,
  Red,
  Green,
  Blue,
  ShortRange,
  LongRange,
};
constexpr int kLuaKeyCount = static_cast<int>(LuaKey::LongRange);
/// Registry references to one state's key strings, by LuaKey (-1: not used yet). Made at
/// the first push, soon after the device tables' own: the registry slots a refill reads
/// lie close together.
struct LuaKeyRefs {
  int ref[kLuaKeyCount + 1];
  LuaKeyRefs() {
    for (int& r : ref) r = -1;
  }
};

/// Registry references to each device table of one robot (-1: absent).
struct LuaDeviceRefs {
  /// robot.<lua_key> of each device, indexed by DeviceType. An actuator and a sensor with
  /// the same key (wheels, turret...) share the table and its reference.
  int table[kDeviceCount];
  LuaKeyRefs keys;
  int rab_count = 0;   // messages currently in robot.range_and_bearing
  int blob_count = 0;  // blobs currently in the camera table
  // distance scanner: the short_range / long_range arrays, the pools of their 12 inner
  // {angle, distance} tables (reused, never reallocated), and their current lengths
  int scanner_short = -1, scanner_long = -1, scanner_short_pool = -1, scanner_long_pool = -1;
  int scanner_short_count = 0, scanner_long_count = 0;
  LuaDeviceRefs() {
    for (int& ref : table) ref = -1;
  }
};

}  // namespace essaim
