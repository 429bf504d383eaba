// Per-robot handles to its Lua device tables; no Lua header, so the sim layer can hold it.
#pragma once
#include "model/device_table.h"

namespace essaim {

/// Registry references to each device table of one robot (-1: absent).
struct LuaDeviceRefs {
  /// robot.<lua_key> of each device, indexed by DeviceType. An actuator and a sensor with
  /// the same key (wheels, turret...) share the table and its reference.
  int table[kDeviceCount];
  int keys = -1;       // the state's table of reading keys (LuaKey, lua_devices.h)
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
