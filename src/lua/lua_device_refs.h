// Per-robot handles to its Lua device tables; no Lua header, so the sim layer can hold it.
#pragma once

namespace essaim {

/// Registry references to each device table of one robot (-1: absent).
struct LuaDeviceRefs {
  int wheels = -1, positioning = -1, battery = -1, proximity = -1, light = -1, base_ground = -1,
      motor_ground = -1, rab = -1, scanner = -1, camera = -1, turret = -1, leds = -1, gripper = -1;
  int rab_count = 0;       // messages currently in robot.range_and_bearing
  int blob_count = 0;      // blobs currently in the camera table
  bool camera_enabled = false;
};

}  // namespace essaim
