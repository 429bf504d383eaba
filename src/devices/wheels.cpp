// Differential steering actuator and sensor.
#include "devices/devices.h"

namespace essaim {

void InitWheelNoise(const DeviceConfig& cfg, RobotState& robot) {
  const DeviceParams& p = cfg.params;
  if (!p.wheel_noise) return;
  // Bias drawn once per robot (ARGoS); absent bias attributes mean 0 (an ARGoS quirk).
  robot.wheel_bias_left = robot.actuator_rng.Gaussian(p.bias_stddev[0], p.bias_avg[0]);
  robot.wheel_bias_right = robot.actuator_rng.Gaussian(p.bias_stddev[1], p.bias_avg[1]);
}

void ActWheels(const DeviceConfig* cfg, RobotState& robot, PhysicsWorld& physics) {
  if (robot.cmd.wheels_new) {
    robot.cmd.wheels_new = false;
    double l = robot.cmd.wheel_left, r = robot.cmd.wheel_right;
    if (cfg && cfg->params.wheel_noise && (l != 0 || r != 0)) {
      const DeviceParams& p = cfg->params;
      auto factor = [&](int w) {
        return p.factor_stddev[w] > 0 ? robot.actuator_rng.Gaussian(p.factor_stddev[w], p.factor_avg[w])
                                      : p.factor_avg[w];
      };
      double fl = factor(0), fr = factor(1);
      l = fl * (l + robot.wheel_bias_left);
      r = fr * (r + robot.wheel_bias_right);
    }
    robot.wheel_left = l;
    robot.wheel_right = r;
  }
  physics.SetWheelSpeeds(robot.index, robot.wheel_left, robot.wheel_right);
}

void SenseWheels(const DeviceConfig& cfg, RobotState& robot, double dt) {
  // ARGoS reports the commanded (applied) speeds, not measured motion.
  double vl = robot.wheel_left * 100, vr = robot.wheel_right * 100;
  double dl = vl * dt, dr = vr * dt;
  const NoiseRange& vn = cfg.params.vel_noise;
  const NoiseRange& dn = cfg.params.dist_noise;
  if (vn.On()) {
    vl += robot.sensor_rng.Uniform(vn.lo, vn.hi);
    vr += robot.sensor_rng.Uniform(vn.lo, vn.hi);
  }
  if (dn.On()) {
    dl += robot.sensor_rng.Uniform(dn.lo, dn.hi);
    dr += robot.sensor_rng.Uniform(dn.lo, dn.hi);
  }
  robot.rd.velocity_left = vl;
  robot.rd.velocity_right = vr;
  robot.rd.distance_left = dl;
  robot.rd.distance_right = dr;
}

}  // namespace essaim
