#include "devices/devices.h"

#include "devices/device_functions.h"

namespace essaim {

void InitRobotState(const Model& model, int index, RobotState& robot, const PhysicsWorld& physics) {
  const uint64_t seed = model.experiment.seed;
  const uint64_t i = static_cast<uint64_t>(index);
  robot.index = index;
  robot.controller_rng.Seed(DeriveSeed(seed, StreamKind::Controller, i));
  robot.sensor_rng.Seed(DeriveSeed(seed, StreamKind::SensorNoise, i));
  robot.actuator_rng.Seed(DeriveSeed(seed, StreamKind::ActuatorNoise, i));
  InitRobotDevices(model, model.robots[index], robot, physics);
}

void InitRobotDevices(const Model& model, const RobotDef& def, RobotState& robot, const PhysicsWorld& physics) {
  const ControllerDef& c = model.controllers[def.controller];
  robot.cmd.rab_data.assign(def.rab_data_size, 0);
  robot.rab_data.assign(def.rab_data_size, 0);
  InitBattery(def.battery, robot, physics.RobotPose(robot.index));
  const InitContext ctx{model, physics};
  for (const std::vector<DeviceConfig>* list : {&c.actuators, &c.sensors})
    for (const DeviceConfig& d : *list)
      if (InitFn init = FunctionsOf(d.type).init) init(ctx, d, def, robot);
}

namespace {
void ActPhaseOf(ActPhase phase, const Model& model, const RobotDef& def, RobotState& robot, PhysicsWorld& physics) {
  if (!robot.alive) return;
  const ActContext ctx{model, physics, model.experiment.TickLength()};
  for (const DeviceConfig& d : model.controllers[def.controller].actuators) {
    const DeviceFunctions& f = FunctionsOf(d.type);
    if (f.act_phase == phase) f.act(ctx, d, def, robot);
  }
}
}  // namespace

void ActRobotOwnState(const Model& model, const RobotDef& def, RobotState& robot, PhysicsWorld& physics) {
  ActPhaseOf(ActPhase::OwnState, model, def, robot, physics);
}

void ActRobotJoints(const Model& model, const RobotDef& def, RobotState& robot, PhysicsWorld& physics) {
  ActPhaseOf(ActPhase::Joints, model, def, robot, physics);
}

void UpdateRobotComponents(const Model& model, const RobotDef& def, RobotState& robot, const PhysicsWorld& physics,
                           uint64_t tick) {
  if (!robot.alive) return;
  DischargeBattery(def.battery, robot, physics.RobotPose(robot.index), tick);
  UpdateScanner(robot, model.experiment.TickLength());
}

void SenseRobot(const SenseContext& ctx, const RobotDef& def, RobotState& robot) {
  for (const DeviceConfig& d : ctx.model.controllers[def.controller].sensors)
    FunctionsOf(d.type).sense(ctx, d, def, robot);
}

}  // namespace essaim
