// What one robot's C++ controller reaches of its robot, in plain types: the readings its
// sensors took this tick and the commands it sets for the next act. The host implements it
// over the robot's RobotState (argos/robot_io.cpp), the very values the Lua tables are made
// from, so a C++ controller sees what a Lua one sees; the ARGoS API library's sensor and
// actuator classes (api/) turn them into ARGoS's layouts. Units are ARGoS's control
// interface's: cm, cm/s, rad.
#pragma once
#include <cstdint>
#include <string>

#include "argos/argos_world.h"

namespace essaim {

struct ArgosRabPacket {
  double range = 0;               // cm
  double horizontal_bearing = 0;  // rad
  double vertical_bearing = 0;    // rad
  const uint8_t* data = nullptr;  // the sender's payload, valid during the control step
  int size = 0;
};

struct ArgosBlob {
  double distance = 0;  // cm
  double angle = 0;     // rad
  ArgosRgb color;
  uint8_t alpha = 255;
};

struct ArgosScan {
  double angle = 0;     // rad, robot frame
  double distance = 0;  // cm; -1 too close, -2 nothing in range (as the Lua table)
};

/// Ground sensors' points: {x, y} in cm, robot frame, one row a sensor.
using ArgosOffsets = const double (*)[2];

enum class ArgosTurretMode { Off, Passive, Position, Speed };

class ArgosRobotIo {
 public:
  virtual ~ArgosRobotIo() = default;

  // ---- readings of this tick (sensors the controller declares; others read zeros)
  /// The 24 proximity values and their angles (robot.proximity[k].value / .angle).
  virtual const double* Proximity() const = 0;
  virtual const double* ProximityAngles() const = 0;
  virtual const double* Light() const = 0;  // 24, angles as the proximity's
  /// Ground: values and offsets {x, y} in cm, robot frame (4 motor, 8 base).
  virtual const double* MotorGround() const = 0;
  virtual ArgosOffsets MotorGroundOffsets() const = 0;
  virtual const double* BaseGround() const = 0;
  virtual ArgosOffsets BaseGroundOffsets() const = 0;
  /// Position in m, orientation as a unit quaternion {w, x, y, z}.
  virtual void Positioning(double position[3], double quaternion[4]) const = 0;
  /// Wheels' velocity (cm/s) and covered distance (cm, last tick), left and right; the axis in cm.
  virtual void WheelReading(double velocity[2], double distance[2], double* axis_length) const = 0;
  virtual int RabCount() const = 0;
  virtual ArgosRabPacket Rab(int k) const = 0;
  /// Blobs in the camera's order; none while the camera is disabled.
  virtual int BlobCount() const = 0;
  virtual ArgosBlob Blob(int k) const = 0;
  /// Distance scanner: `short_range` picks the short or long sensors' readings of this tick.
  virtual int ScanCount(bool short_range) const = 0;
  virtual ArgosScan Scan(bool short_range, int k) const = 0;
  virtual double TurretRotation() const = 0;  // rad
  /// Battery: available charge (0..1) and time left in s (+inf when not discharging).
  virtual void Battery(double* charge, double* time_left) const = 0;

  // ---- commands (applied at the next act, as Lua's)
  /// cm/s. False (nothing set) when either is not finite: the controller is stopped with
  /// an error naming the call.
  virtual bool SetWheels(double left, double right) = 0;
  virtual int LedCount() const = 0;  // 13: index 12 is the beacon
  virtual void SetLed(int k, const ArgosRgb& color, uint8_t alpha) = 0;
  /// The payload sent from the next act on: `RabDataSize()` bytes, written in place.
  virtual uint8_t* RabData() = 0;
  virtual int RabDataSize() const = 0;
  virtual void SetGripperAperture(double radians) = 0;  // +pi/2, -pi/2 locked; 0 unlocked
  virtual void SetCameraEnabled(bool enabled) = 0;
  virtual bool CameraEnabled() const = 0;
  // The distance scanner's and the turret's operations, as the Lua table's functions of the
  // same names (robot.distance_scanner.*, robot.turret.*) do them.
  virtual void ScannerEnable() = 0;
  virtual void ScannerDisable() = 0;
  virtual void ScannerSetAngle(double radians) = 0;
  virtual void ScannerSetRpm(double rpm) = 0;
  virtual void TurretSetRotation(double radians) = 0;
  virtual void TurretSetRotationSpeed(double speed) = 0;  // the argument of set_rotation_speed
  virtual void TurretSetMode(ArgosTurretMode mode) = 0;
};

}  // namespace essaim
