// Per-robot handles to its Lua device tables; no Lua header, so the sim layer can hold it.
#pragma once

namespace essaim {

/// Registry references to each device table of one robot (-1: absent).
struct LuaDeviceRefs {
  int wheels = -1, positioning = -1, battery = -1, proximity = -1, light = -1, base_ground = -1,
      motor_ground = -1, rab = -1, scanner = -1, camera = -1, turret = -1, leds = -1, gripper = -1;
  int rab_count = 0;       // messages currently in robot.range_and_bearing
  int blob_count = 0;      // blobs currently in the camera table
  // distance scanner: the short_range / long_range arrays, the pools of their 12 inner
  // {angle, distance} tables (reused, never reallocated), and their current lengths
  int scanner_short = -1, scanner_long = -1, scanner_short_pool = -1, scanner_long_pool = -1;
  int scanner_short_count = 0, scanner_long_count = 0;
  bool camera_enabled = false;
};

}  // namespace essaim
