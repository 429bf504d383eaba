// Per-robot mutable state: what the controller commands, what the sensors read, and each
// device's internal state. Plain, fixed-size data allocated when the World is built, so
// the step never allocates; each robot's sense and control touch only its own RobotState
// (what lets robots run on several threads without locks).
#pragma once
#include <cstdint>
#include <deque>
#include <vector>

#include "core/math.h"
#include "core/rng.h"
#include "model/model.h"
#include "physics/physics_world.h"

namespace essaim {

enum class ScannerMode { Off, Position, Speed };
enum class TurretMode { Off, Passive, Position, Speed };

/// Written by Lua bindings during step(); applied in the next Act stage.
struct Commands {
  double wheel_left = 0, wheel_right = 0;  // m/s as requested
  bool wheels_new = false;                 // set_velocity called since the last Act
  Color leds[footbot::kLedCount];
  std::vector<uint8_t> rab_data;  // rab_data_size bytes
  ScannerMode scanner_mode = ScannerMode::Off;
  double scanner_angle = 0;     // rad, position mode
  double scanner_speed = 0;     // rad/s, speed mode
  double gripper_aperture = 0;  // rad: +pi/2 lock positive, -pi/2 negative, 0 unlocked
  TurretMode turret_mode = TurretMode::Off;
  double turret_rotation = 0;  // rad
  double turret_speed = 0;     // rad/s
};

struct RabPacket {
  double range = 0;               // cm
  double horizontal_bearing = 0;  // rad
  double vertical_bearing = 0;    // rad
  int sender = -1;                // robot index
  const uint8_t* data = nullptr;  // sender's applied payload (valid during sense/control)
  int size = 0;
};

struct ScanReading {
  double angle = 0;     // rad, robot frame
  double distance = 0;  // cm, -1 too close, -2 nothing
};

struct Blob {
  double distance = 0;  // cm
  double angle = 0;     // rad
  Color color;
  int led = -1;  // index into Media::leds: the blobs' order
};

/// Written by the Sense stage; copied into the robot's Lua tables before step().
struct Readings {
  double velocity_left = 0, velocity_right = 0;  // cm/s
  double distance_left = 0, distance_right = 0;  // cm during the last tick
  Vec3 position = Vec3::Zero();                  // m
  double quat_w = 1, quat_x = 0, quat_y = 0, quat_z = 0;
  double proximity[24] = {};
  double light[24] = {};
  double base_ground[8] = {};
  double motor_ground[4] = {};
  int scanner_short_count = 0, scanner_long_count = 0;
  ScanReading scanner_short[12], scanner_long[12];
  std::vector<RabPacket> rab;    // capacity reserved: robots - 1
  std::vector<Blob> blobs;       // capacity reserved
  double battery_charge = 1;     // available_charge
  double battery_time_left = 0;  // s; +inf when not discharging
  double turret_rotation = 0;    // rad
};

struct BatteryState {
  double charge = 1;  // absolute
  double last_reading = 1;
  Vec2 last_position = Vec2::Zero();
  double last_yaw = 0;
};

struct ScannerState {
  ScannerMode mode = ScannerMode::Off;
  double rotation = 0;           // rad, platform angle now
  double previous_rotation = 0;  // at the previous sensor update
  double speed = 0;              // rad/s
};

struct RobotState {
  int index = 0;
  bool alive = true;
  bool controller_ok = true;
  Commands cmd;
  Readings rd;
  Rng controller_rng;  // robot.random
  Rng sensor_rng;      // noise of this robot's sensors
  Rng actuator_rng;    // noise of this robot's actuators
  // Applied actuator state (what the world sees), set in Act.
  double wheel_left = 0, wheel_right = 0;  // m/s after noise
  double wheel_bias_left = 0, wheel_bias_right = 0;
  Color leds[footbot::kLedCount];
  std::vector<uint8_t> rab_data;  // applied payload, broadcast this tick
  bool camera_enabled = false;    // colored_blob_omnidirectional_camera enable()/disable()
  double gripper_aperture = 0;
  double turret_rotation = 0;  // rad relative to the body, in [-pi, pi] (devices/turret.cpp)
  TurretMode turret_mode = TurretMode::Off;
  double turret_previous_error = 0;  // rad, position mode's last error (the PD's D term)
  BatteryState battery;
  ScannerState scanner;
  // Shapes near the robot, gathered once per tick for all rays of one sensor (scratch,
  // capacity kept: no allocation once the densest neighbourhood has been seen).
  RayCandidates proximity_candidates;
  RayCandidates scanner_candidates;  // speed mode: within the short sensors' reach only
  RayCandidates scanner_wedge;       // near the sector a long sensor sweeps (distance_scanner.cpp)
};

/// Every robot's state, by index. A deque: robots that loop functions add during a run
/// join at the end while every other robot's state stays where it is (controllers' Lua
/// closures and robot.random hold pointers into their own robot's state).
using RobotStates = std::deque<RobotState>;

}  // namespace essaim
