// Battery. Deviation: essaim discharges any robot with a <battery> element, with
// or without the battery sensor (ARGoS only when the sensor is declared), so experiment
// rules such as foraging's hold for every controller; the first motion update does not
// charge for the initial yaw (ARGoS quirk). Both are in docs/compatibility.md.
#include <algorithm>
#include <cmath>
#include <limits>

#include "devices/devices.h"

namespace essaim {

void InitBattery(const BatteryDef& def, RobotState& robot, const Pose2& pose) {
  robot.battery.charge = def.start_charge;
  robot.battery.last_reading = def.start_charge / def.full_charge;
  robot.battery.last_position = {pose.x, pose.y};
  robot.battery.last_yaw = pose.yaw;
  robot.rd.battery_charge = robot.battery.last_reading;
  robot.rd.battery_time_left = std::numeric_limits<double>::infinity();
}

void DischargeBattery(const BatteryDef& def, RobotState& robot, const Pose2& pose, uint64_t tick) {
  BatteryState& b = robot.battery;
  if (tick == 0 || def.model == DischargeModel::None) return;
  Vec2 pos(pose.x, pose.y);
  double moved = (pos - b.last_position).norm();
  double turned = std::fabs(WrapSigned(pose.yaw - b.last_yaw));
  b.last_position = pos;
  b.last_yaw = pose.yaw;
  double delta = 0;
  switch (def.model) {
    case DischargeModel::Time:
      delta = def.delta;
      break;
    case DischargeModel::Motion:
      delta = def.pos_delta * moved + def.orient_delta * turned;
      break;
    case DischargeModel::TimeMotion:
      delta = def.time_factor + def.pos_factor * moved + def.orient_factor * turned;
      break;
    case DischargeModel::None:
      break;
  }
  b.charge = std::max(0.0, b.charge - delta);
}

void SenseBattery(const DeviceConfig& cfg, const BatteryDef& def, RobotState& robot, double dt) {
  double reading = robot.battery.charge / def.full_charge;
  const NoiseRange& n = cfg.params.charge_noise;
  if (n.On()) reading = std::clamp(reading + robot.sensor_rng.Uniform(n.lo, n.hi), 0.0, 1.0);
  double old = robot.battery.last_reading;
  if (robot.battery.charge <= 0)
    robot.rd.battery_time_left = 0;
  else if (old - reading > 1e-6)
    robot.rd.battery_time_left = old * dt / (old - reading);
  else
    robot.rd.battery_time_left = std::numeric_limits<double>::infinity();
  robot.rd.battery_charge = reading;
  robot.battery.last_reading = reading;
}

}  // namespace essaim
