// What a controller's calls set in its robot's Commands, one function a call, shared by the
// Lua bindings (lua/robot/bind_*.cpp) and the C++ controllers' ARGoS interface
// (argos/robot_io.cpp), so that a call means the same in both. Arguments are checked
// (finite numbers, indices in range) by the callers, which report in their own language.
#pragma once
#include <algorithm>

#include "core/math.h"
#include "devices/robot_state.h"

namespace essaim {

constexpr double kMaxWheelSpeed = 10.0;  // m/s: 1 m per tick at 10 ticks/s, under Box2D's 2 m step cap
constexpr double kMaxTurretSpeed = 20 * 3.141592653589793;  // rad/s (600 in set_rotation_speed units)

/// Wheel speeds in cm/s, as ARGoS's set_velocity and SetLinearVelocity take them.
inline void SetWheelVelocity(RobotState& r, double left, double right) {
  r.cmd.wheel_left = std::clamp(left * 0.01, -kMaxWheelSpeed, kMaxWheelSpeed);
  r.cmd.wheel_right = std::clamp(right * 0.01, -kMaxWheelSpeed, kMaxWheelSpeed);
  r.cmd.wheels_new = true;
}

inline void ScannerEnable(RobotState& r) { r.cmd.scanner_mode = ScannerMode::Position; }  // at the last angle
inline void ScannerDisable(RobotState& r) { r.cmd.scanner_mode = ScannerMode::Off; }
inline void ScannerSetAngle(RobotState& r, double radians) {
  r.cmd.scanner_mode = ScannerMode::Position;
  r.cmd.scanner_angle = radians;
}
inline void ScannerSetRpm(RobotState& r, double rpm) {
  r.cmd.scanner_mode = ScannerMode::Speed;
  r.cmd.scanner_speed = rpm * kPi / 30;
}

inline void TurretSetRotation(RobotState& r, double radians) { r.cmd.turret_rotation = radians; }
/// `x` as set_rotation_speed takes it: x·π/30 rad/s.
inline void TurretSetRotationSpeed(RobotState& r, double x) {
  r.cmd.turret_speed = std::clamp(x * kPi / 30, -kMaxTurretSpeed, kMaxTurretSpeed);
}
inline void TurretSetMode(RobotState& r, TurretMode mode) { r.cmd.turret_mode = mode; }

/// +π/2 locked positive, -π/2 locked negative, 0 unlocked.
inline void SetGripperAperture(RobotState& r, double radians) { r.cmd.gripper_aperture = radians; }

}  // namespace essaim
