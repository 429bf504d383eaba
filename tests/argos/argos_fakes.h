// Fakes for the ARGoS API library's own tests: a world with no entities and one robot's
// readings and commands as plain fields the test sets and reads.
#pragma once
#include <cmath>
#include <string>
#include <vector>

#include "argos/argos_robot_io.h"
#include "argos/argos_world.h"

namespace essaim {

class FakeWorld : public ArgosWorld {
 public:
  uint64_t tick = 0, seed = 12345;
  std::vector<std::string> log;     // "O text" / "E text"
  std::vector<std::string> robots;  // foot-bots' ids, by index
  uint64_t Tick() const override { return tick; }
  uint64_t Seed() const override { return seed; }
  uint64_t LengthTicks() const override { return 0; }
  double TickLength() const override { return 0.1; }
  void Arena(double size[3], double center[3]) const override {
    for (int i = 0; i < 3; ++i) size[i] = 4, center[i] = 0;
  }
  std::vector<std::string> LedMedia() const override { return {}; }
  std::vector<ArgosRef> Entities(int kind) const override {
    std::vector<ArgosRef> out;
    if (kind <= kArgosFootBot)
      for (uint32_t i = 0; i < robots.size(); ++i) out.push_back({kArgosFootBot, i});
    return out;
  }
  uint64_t LayoutVersion() const override { return robots.size(); }
  bool Live(const ArgosRef& e) const override { return e.kind == kArgosFootBot && e.serial < robots.size(); }
  std::string Id(const ArgosRef& e) const override { return Live(e) ? robots[e.serial] : ""; }
  bool Pose(const ArgosRef& e, ArgosPose*) const override { return Live(e); }
  bool Movable(const ArgosRef&) const override { return false; }
  bool Move(const ArgosRef&, const ArgosPose&, bool, bool) override { return false; }
  ArgosBody Body(const ArgosRef&) const override { return {}; }
  int LedCount(const ArgosRef&) const override { return 0; }
  ArgosRgb Led(const ArgosRef&, int) const override { return {}; }
  void SetLed(const ArgosRef&, int, const ArgosRgb&) override {}
  void SetMedium(const ArgosRef&, const std::string&) override {}
  ArgosLight Light(const ArgosRef&) const override { return {}; }
  void SetLight(const ArgosRef&, const ArgosLight&) override {}
  bool Add(const ArgosBody&, ArgosRef*, std::string*) override { return false; }
  bool Add(const ArgosLight&, ArgosRef*, std::string*) override { return false; }
  bool Add(const ArgosRobot&, ArgosRef*, std::string*) override { return false; }
  bool Remove(const ArgosRef&) override { return false; }
  std::string ControllerId(uint32_t) const override { return ""; }
  lua_State* LuaState(uint32_t) override { return nullptr; }
  bool ControllerOk(uint32_t) const override { return true; }
  void Log(bool error, const std::string& line) override { log.push_back((error ? "E " : "O ") + line); }
  void FloorChanged() override {}
};

struct FakeLed {
  ArgosRgb color;
  uint8_t alpha = 0;
  int sets = 0;
};

class FakeRobotIo : public ArgosRobotIo {
 public:
  // ---- readings the test sets
  double proximity[24] = {}, proximity_angles[24] = {}, light[24] = {};
  double motor_ground[4] = {}, motor_offsets[4][2] = {}, base_ground[8] = {}, base_offsets[8][2] = {};
  double position[3] = {}, quaternion[4] = {1, 0, 0, 0};
  double wheel_velocity[2] = {}, wheel_distance[2] = {}, axis = 14;
  std::vector<ArgosRabPacket> rab;
  std::vector<ArgosBlob> blobs;  // what the camera sees while enabled
  std::vector<ArgosScan> short_scans, long_scans;
  double turret_rotation = 0, charge = 1, time_left = INFINITY;
  // ---- commands the test reads
  double wheels[2] = {};
  FakeLed leds[13];
  std::vector<uint8_t> rab_data = std::vector<uint8_t>(4, 0);
  double gripper = 0;
  bool camera = false;
  std::vector<std::string> calls;  // scanner and turret operations, in order

  const double* Proximity() const override { return proximity; }
  const double* ProximityAngles() const override { return proximity_angles; }
  const double* Light() const override { return light; }
  const double* MotorGround() const override { return motor_ground; }
  const double (*MotorGroundOffsets() const)[2] { return motor_offsets; }
  const double* BaseGround() const override { return base_ground; }
  const double (*BaseGroundOffsets() const)[2] { return base_offsets; }
  void Positioning(double p[3], double q[4]) const override {
    for (int i = 0; i < 3; ++i) p[i] = position[i];
    for (int i = 0; i < 4; ++i) q[i] = quaternion[i];
  }
  void WheelReading(double v[2], double d[2], double* a) const override {
    v[0] = wheel_velocity[0], v[1] = wheel_velocity[1], d[0] = wheel_distance[0], d[1] = wheel_distance[1];
    *a = axis;
  }
  int RabCount() const override { return static_cast<int>(rab.size()); }
  ArgosRabPacket Rab(int k) const override { return rab[k]; }
  int BlobCount() const override { return camera ? static_cast<int>(blobs.size()) : 0; }
  ArgosBlob Blob(int k) const override { return blobs[k]; }
  int ScanCount(bool s) const override { return static_cast<int>((s ? short_scans : long_scans).size()); }
  ArgosScan Scan(bool s, int k) const override { return (s ? short_scans : long_scans)[k]; }
  double TurretRotation() const override { return turret_rotation; }
  void Battery(double* c, double* t) const override { *c = charge, *t = time_left; }

  bool SetWheels(double left, double right) override {
    if (!std::isfinite(left) || !std::isfinite(right)) return false;
    wheels[0] = left, wheels[1] = right;
    return true;
  }
  int LedCount() const override { return 13; }
  void SetLed(int k, const ArgosRgb& color, uint8_t alpha) override {
    leds[k].color = color, leds[k].alpha = alpha, ++leds[k].sets;
  }
  uint8_t* RabData() override { return rab_data.data(); }
  int RabDataSize() const override { return static_cast<int>(rab_data.size()); }
  void SetGripperAperture(double radians) override { gripper = radians; }
  void SetCameraEnabled(bool enabled) override { camera = enabled; }
  bool CameraEnabled() const override { return camera; }
  void ScannerEnable() override { calls.push_back("scanner enable"); }
  void ScannerDisable() override { calls.push_back("scanner disable"); }
  void ScannerSetAngle(double r) override { calls.push_back("scanner angle " + std::to_string(r)); }
  void ScannerSetRpm(double rpm) override { calls.push_back("scanner rpm " + std::to_string(rpm)); }
  void TurretSetRotation(double r) override { calls.push_back("turret rotation " + std::to_string(r)); }
  void TurretSetRotationSpeed(double s) override { calls.push_back("turret speed " + std::to_string(s)); }
  void TurretSetMode(ArgosTurretMode m) override { calls.push_back("turret mode " + std::to_string(int(m))); }
};

}  // namespace essaim
