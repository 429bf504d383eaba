// Device stages as free functions over plain data: Act applies commands to the world,
// Sense fills Readings. Each device's functions are found through its row in
// device_functions.cpp, indexed by DeviceType as model/device_table.h's rows.
#pragma once
#include "devices/floor.h"
#include "devices/media.h"
#include "devices/robot_state.h"
#include "model/model.h"
#include "physics/physics_world.h"

namespace essaim {

/// Read-only view of the world that sensing needs; shared by all threads.
struct SenseContext {
  const Model& model;
  const PhysicsWorld& physics;
  const Media& media;
  const FloorRaster& floor;
  const RobotStates& robots;  // other robots' applied actuator state
  uint64_t tick = 0;
  double dt = 0.1;
};

/// Robot `index`'s state made anew (its body already in the physics): its random streams
/// from the experiment's seed, then InitRobotDevices. At World creation, and for a robot
/// that loop functions add during the run.
void InitRobotState(const Model& model, int index, RobotState& robot, const PhysicsWorld& physics);
/// Called once when the World is built (noise biases, buffers, initial readings).
void InitRobotDevices(const Model& model, const RobotDef& def, RobotState& robot, const PhysicsWorld& physics);
/// Act stage for one robot, part one: the actuators that write only the robot's own state
/// and its own wheel servo (wheels, scanner, LEDs, range-and-bearing). Safe to run for
/// distinct robots on several threads at once.
void ActRobotOwnState(const Model& model, const RobotDef& def, RobotState& robot, PhysicsWorld& physics);
/// Part two: the actuators that write into the shared physics world (the gripper's lock,
/// then the turret's disc, in tag order). One thread, robots in index order, so they are
/// written in the same order at any thread count. The two parts touch disjoint state, so
/// running all of part one first gives what one ordered pass per robot gives.
void ActRobotJoints(const Model& model, const RobotDef& def, RobotState& robot, PhysicsWorld& physics);
/// After physics: per-robot component updates (battery discharge, scanner rotation).
void UpdateRobotComponents(const Model& model, const RobotDef& def, RobotState& robot, const PhysicsWorld& physics,
                           uint64_t tick);
/// Sense stage for one robot: every sensor, alphabetical tag order. Writes only `robot`.
void SenseRobot(const SenseContext& ctx, const RobotDef& def, RobotState& robot);

// ---- per-device functions (one file each)
void ActWheels(const DeviceConfig* cfg, RobotState& robot, PhysicsWorld& physics);
void InitWheelNoise(const DeviceConfig& cfg, RobotState& robot);
void SenseWheels(const DeviceConfig& cfg, RobotState& robot, double dt);
void SensePositioning(const DeviceConfig& cfg, RobotState& robot, const PhysicsWorld& physics);
void InitBattery(const BatteryDef& def, RobotState& robot, const Pose2& pose);
void DischargeBattery(const BatteryDef& def, RobotState& robot, const Pose2& pose, uint64_t tick);
void SenseBattery(const DeviceConfig& cfg, const BatteryDef& def, RobotState& robot, double dt);

// ---- ray and ground sensors (proximity.cpp, distance_scanner.cpp, light.cpp, ground.cpp)
constexpr int kRingSensorCount = 24;  // proximity and light rings
constexpr int kBaseGroundCount = 8;
constexpr int kMotorGroundCount = 4;
/// Angle of ring sensor k (0..23), robot frame: 7.5° + 15°·k, signed-normalized (rad).
double RingSensorAngle(int k);
/// Proximity value for a hit at `d` m from the ray start: 1 when saturated, then ARGoS's
/// decreasing curve (proximity.cpp).
double ProximityValue(double d);
/// Ground sensor points in the robot frame (cm, x forward, y left).
extern const double kBaseGroundOffsets[kBaseGroundCount][2];
extern const double kMotorGroundOffsets[kMotorGroundCount][2];
void SenseProximity(const DeviceConfig& cfg, RobotState& robot, const PhysicsWorld& physics);
void ActScanner(RobotState& robot);
/// After physics: speed mode advances the platform by speed·dt, wrapped into [0, 2π).
void UpdateScanner(RobotState& robot, double dt);
void SenseScanner(RobotState& robot, const PhysicsWorld& physics);
/// Whether a shape blocks the 3D segment from → light (robot `self` ignored).
bool LightOccluded(const Model& model, const PhysicsWorld& physics, int self, const Vec3& from, const Vec3& light);
void SenseLight(const DeviceConfig& cfg, const Model& model, const RobotDef& def, RobotState& robot,
                const PhysicsWorld& physics);
void SenseBaseGround(const DeviceConfig& cfg, RobotState& robot, const PhysicsWorld& physics, const FloorRaster& floor);
void SenseMotorGround(const DeviceConfig& cfg, RobotState& robot, const PhysicsWorld& physics,
                      const FloorRaster& floor);
// ---- gripper and turret (gripper.cpp, turret.cpp)
/// Hands the lock to the physics: locked, it grips what touches the gripper disc (if holding
/// nothing); unlocked, it lets go at the disc's next contact (ARGoS's rule).
void ActGripper(RobotState& robot, PhysicsWorld& physics);
/// Advances the turret by one tick of `dt` s in its mode and turns the gripper disc with it.
void ActTurret(RobotState& robot, PhysicsWorld& physics, double dt);
void SenseTurretEncoder(RobotState& robot);
// ---- LEDs, range and bearing, camera (leds.cpp, range_and_bearing.cpp, camera.cpp)
void ActLeds(RobotState& robot);
void ActRab(RobotState& robot);
void SenseRab(const SenseContext& ctx, const DeviceConfig& cfg, RobotState& robot);
void SenseCamera(const SenseContext& ctx, const DeviceConfig& cfg, const RobotDef& def, RobotState& robot);

}  // namespace essaim
