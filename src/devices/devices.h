// Device stages as free functions over plain data: Act applies commands to the world,
// Sense fills Readings. Dispatch is a switch on DeviceType (devices.cpp) — one case per
// row of model/device_table.
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
  const std::vector<RobotState>& robots;  // other robots' applied actuator state
  uint64_t tick = 0;
  double dt = 0.1;
};

/// Called once when the World is built (noise biases, buffers, initial readings).
void InitRobotDevices(const Model& model, const RobotDef& def, RobotState& robot, const PhysicsWorld& physics);
/// Act stage for one robot: every actuator of its controller, in alphabetical tag order.
void ActRobot(const Model& model, const RobotDef& def, RobotState& robot, PhysicsWorld& physics);
/// After physics: per-robot component updates (battery discharge, scanner rotation).
void UpdateRobotComponents(const Model& model, const RobotDef& def, RobotState& robot,
                           const PhysicsWorld& physics, uint64_t tick);
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
// ---- gripper and turret (gripper.cpp, turret.cpp; spec §7.5)
/// Locked: grips what touches the gripper disc (if holding nothing); unlocked: releases.
void ActGripper(RobotState& robot, PhysicsWorld& physics);
/// Advances the turret by one tick of `dt` s in its mode and turns a held object with it.
void ActTurret(RobotState& robot, PhysicsWorld& physics, double dt);
void SenseTurretEncoder(RobotState& robot);

}  // namespace essaim
