#include "devices/devices.h"

#include <algorithm>

namespace essaim {

void InitRobotDevices(const Model& model, const RobotDef& def, RobotState& robot, const PhysicsWorld& physics) {
  const ControllerDef& c = model.controllers[def.controller];
  robot.cmd.rab_data.assign(def.rab_data_size, 0);
  robot.rab_data.assign(def.rab_data_size, 0);
  // Bounded reservations (a full n-1 per robot would be O(n^2) memory): the vectors grow
  // to the densest neighbourhood seen, then stay.
  if (c.Has(DeviceType::RabSensor)) robot.rd.rab.reserve(std::min<size_t>(model.robots.size(), 128));
  if (c.Has(DeviceType::CameraSensor)) robot.rd.blobs.reserve(64);
  if (c.Has(DeviceType::ProximitySensor)) robot.proximity_candidates.items.reserve(16);
  if (c.Has(DeviceType::ScannerSensor)) {
    // The long sensors' sectors turn: a new densest one may come long after the first ticks.
    for (RayCandidates* list : {&robot.scanner_candidates, &robot.scanner_wedge}) {
      list->items.reserve(64);
      list->scratch.reserve(64);
    }
  }
  for (const DeviceConfig& d : c.actuators)
    if (d.type == DeviceType::WheelsActuator) InitWheelNoise(d, robot);
  InitBattery(def.battery, robot, physics.RobotPose(robot.index));
  // Readings visible in init(): the initial pose (spec §12).
  if (const DeviceConfig* p = c.Find(DeviceType::PositioningSensor)) SensePositioning(*p, robot, physics);
}

void ActRobotOwnState(const Model& model, const RobotDef& def, RobotState& robot, PhysicsWorld& physics) {
  const ControllerDef& c = model.controllers[def.controller];
  if (!robot.alive) return;
  for (const DeviceConfig& d : c.actuators) {
    switch (d.type) {
      case DeviceType::WheelsActuator: ActWheels(&d, robot, physics); break;
      case DeviceType::ScannerActuator: ActScanner(robot); break;
      case DeviceType::LedsActuator: ActLeds(robot); break;
      case DeviceType::RabActuator: ActRab(robot); break;
      default: break;
    }
  }
}

void ActRobotJoints(const Model& model, const RobotDef& def, RobotState& robot, PhysicsWorld& physics) {
  const ControllerDef& c = model.controllers[def.controller];
  if (!robot.alive) return;
  for (const DeviceConfig& d : c.actuators) {
    switch (d.type) {
      // The gripper reads the turret angle before the turret turns, as in one ordered pass.
      case DeviceType::GripperActuator: ActGripper(robot, physics); break;
      case DeviceType::TurretActuator: ActTurret(robot, physics, model.experiment.TickLength()); break;
      default: break;
    }
  }
}

void UpdateRobotComponents(const Model& model, const RobotDef& def, RobotState& robot, const PhysicsWorld& physics,
                           uint64_t tick) {
  if (!robot.alive) return;
  DischargeBattery(def.battery, robot, physics.RobotPose(robot.index), tick);
  UpdateScanner(robot, model.experiment.TickLength());
}

void SenseRobot(const SenseContext& ctx, const RobotDef& def, RobotState& robot) {
  const ControllerDef& c = ctx.model.controllers[def.controller];
  for (const DeviceConfig& d : c.sensors) {
    switch (d.type) {
      case DeviceType::WheelsSensor: SenseWheels(d, robot, ctx.dt); break;
      case DeviceType::PositioningSensor: SensePositioning(d, robot, ctx.physics); break;
      case DeviceType::BatterySensor: SenseBattery(d, def.battery, robot, ctx.dt); break;
      case DeviceType::ProximitySensor: SenseProximity(d, robot, ctx.physics); break;
      case DeviceType::LightSensor: SenseLight(d, ctx.model, def, robot, ctx.physics); break;
      case DeviceType::BaseGroundSensor: SenseBaseGround(d, robot, ctx.physics, ctx.floor); break;
      case DeviceType::MotorGroundSensor: SenseMotorGround(d, robot, ctx.physics, ctx.floor); break;
      case DeviceType::ScannerSensor: SenseScanner(robot, ctx.physics); break;
      case DeviceType::TurretEncoderSensor: SenseTurretEncoder(robot); break;
      case DeviceType::RabSensor: SenseRab(ctx, d, robot); break;
      case DeviceType::CameraSensor: SenseCamera(ctx, d, def, robot); break;
      default: break;
    }
  }
}

}  // namespace essaim
