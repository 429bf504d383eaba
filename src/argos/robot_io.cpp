#include "argos/robot_io.h"

#include <cmath>

#include "devices/commands.h"
#include "devices/devices.h"

namespace essaim {

namespace {
// The ring's angles, as the Lua tables hold them (RingSensorAngle).
struct RingAngles {
  double angle[kRingSensorCount];
  RingAngles() {
    for (int k = 0; k < kRingSensorCount; ++k) angle[k] = RingSensorAngle(k);
  }
};
}  // namespace

const double* RobotIo::ProximityAngles() const {
  static const RingAngles ring;
  return ring.angle;
}

ArgosOffsets RobotIo::MotorGroundOffsets() const { return kMotorGroundOffsets; }
ArgosOffsets RobotIo::BaseGroundOffsets() const { return kBaseGroundOffsets; }

void RobotIo::Positioning(double position[3], double quaternion[4]) const {
  for (int k = 0; k < 3; ++k) position[k] = r_.rd.position[k];
  quaternion[0] = r_.rd.quat_w;
  quaternion[1] = r_.rd.quat_x;
  quaternion[2] = r_.rd.quat_y;
  quaternion[3] = r_.rd.quat_z;
}

void RobotIo::WheelReading(double velocity[2], double distance[2], double* axis_length) const {
  velocity[0] = r_.rd.velocity_left;
  velocity[1] = r_.rd.velocity_right;
  distance[0] = r_.rd.distance_left;
  distance[1] = r_.rd.distance_right;
  *axis_length = 14.0;  // cm; 0.14 * 100 is not exactly 14 in binary (as robot.wheels.axis_length)
}

ArgosRabPacket RobotIo::Rab(int k) const {
  const RabPacket& p = r_.rd.rab[static_cast<size_t>(k)];
  return {p.range, p.horizontal_bearing, p.vertical_bearing, p.data, p.size};
}

ArgosBlob RobotIo::Blob(int k) const {
  const essaim::Blob& b = r_.rd.blobs[static_cast<size_t>(k)];
  return {b.distance, b.angle, {b.color.r, b.color.g, b.color.b}, b.color.a};
}

int RobotIo::ScanCount(bool short_range) const {
  return short_range ? r_.rd.scanner_short_count : r_.rd.scanner_long_count;
}

ArgosScan RobotIo::Scan(bool short_range, int k) const {
  const ScanReading& s = short_range ? r_.rd.scanner_short[k] : r_.rd.scanner_long[k];
  return {s.angle, s.distance};
}

void RobotIo::Battery(double* charge, double* time_left) const {
  *charge = r_.rd.battery_charge;
  *time_left = r_.rd.battery_time_left;
}

bool RobotIo::SetWheels(double left, double right) {
  if (!std::isfinite(left) || !std::isfinite(right)) return false;
  SetWheelVelocity(r_, left, right);
  return true;
}

int RobotIo::LedCount() const { return footbot::kLedCount; }

void RobotIo::SetLed(int k, const ArgosRgb& color, uint8_t alpha) {
  if (k < 0 || k >= footbot::kLedCount) return;  // the API checks the index and says so
  r_.cmd.leds[k] = Color{color.r, color.g, color.b, alpha};
}

void RobotIo::SetGripperAperture(double radians) { essaim::SetGripperAperture(r_, radians); }
void RobotIo::ScannerEnable() { essaim::ScannerEnable(r_); }
void RobotIo::ScannerDisable() { essaim::ScannerDisable(r_); }
void RobotIo::ScannerSetAngle(double radians) { essaim::ScannerSetAngle(r_, radians); }
void RobotIo::ScannerSetRpm(double rpm) { essaim::ScannerSetRpm(r_, rpm); }
void RobotIo::TurretSetRotation(double radians) { essaim::TurretSetRotation(r_, radians); }
void RobotIo::TurretSetRotationSpeed(double speed) { essaim::TurretSetRotationSpeed(r_, speed); }

void RobotIo::TurretSetMode(ArgosTurretMode mode) {
  static constexpr TurretMode kModes[] = {TurretMode::Off, TurretMode::Passive, TurretMode::Position,
                                          TurretMode::Speed};
  essaim::TurretSetMode(r_, kModes[static_cast<int>(mode)]);
}

}  // namespace essaim
