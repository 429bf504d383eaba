// ArgosRobotIo over one robot's RobotState: the readings its sensors wrote this tick and the
// commands its controller sets, through the same setters the Lua bindings call
// (devices/commands.h), so that a C++ controller and its Lua twin act alike.
#pragma once
#include "argos/argos_robot_io.h"
#include "devices/robot_state.h"

namespace essaim {

class RobotIo : public ArgosRobotIo {
 public:
  explicit RobotIo(RobotState* robot) : r_(*robot) {}

  const double* Proximity() const override { return r_.rd.proximity; }
  const double* ProximityAngles() const override;
  const double* Light() const override { return r_.rd.light; }
  const double* MotorGround() const override { return r_.rd.motor_ground; }
  ArgosOffsets MotorGroundOffsets() const override;
  const double* BaseGround() const override { return r_.rd.base_ground; }
  ArgosOffsets BaseGroundOffsets() const override;
  void Positioning(double position[3], double quaternion[4]) const override;
  void WheelReading(double velocity[2], double distance[2], double* axis_length) const override;
  int RabCount() const override { return static_cast<int>(r_.rd.rab.size()); }
  ArgosRabPacket Rab(int k) const override;
  int BlobCount() const override { return static_cast<int>(r_.rd.blobs.size()); }
  ArgosBlob Blob(int k) const override;
  int ScanCount(bool short_range) const override;
  ArgosScan Scan(bool short_range, int k) const override;
  double TurretRotation() const override { return r_.rd.turret_rotation; }
  void Battery(double* charge, double* time_left) const override;

  bool SetWheels(double left, double right) override;
  int LedCount() const override;
  void SetLed(int k, const ArgosRgb& color, uint8_t alpha) override;
  uint8_t* RabData() override { return r_.cmd.rab_data.data(); }
  int RabDataSize() const override { return static_cast<int>(r_.cmd.rab_data.size()); }
  void SetGripperAperture(double radians) override;
  void SetCameraEnabled(bool enabled) override { r_.camera_enabled = enabled; }
  bool CameraEnabled() const override { return r_.camera_enabled; }
  void ScannerEnable() override;
  void ScannerDisable() override;
  void ScannerSetAngle(double radians) override;
  void ScannerSetRpm(double rpm) override;
  void TurretSetRotation(double radians) override;
  void TurretSetRotationSpeed(double speed) override;
  void TurretSetMode(ArgosTurretMode mode) override;

 private:
  RobotState& r_;
};

}  // namespace essaim
