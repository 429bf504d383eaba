// Positioning sensor: position in m, orientation as a quaternion built from the
// unwrapped heading, optional uniform noise.
#include <algorithm>
#include <cmath>

#include "devices/devices.h"

namespace essaim {

void SensePositioning(const DeviceConfig& cfg, RobotState& robot, const PhysicsWorld& physics) {
  Pose2 pose = physics.RobotPose(robot.index);
  Readings& rd = robot.rd;
  rd.position = Vec3(pose.x, pose.y, 0);
  double half = pose.yaw / 2;
  rd.quat_w = std::cos(half);
  rd.quat_x = 0;
  rd.quat_y = 0;
  rd.quat_z = std::sin(half);
  const DeviceParams& p = cfg.params;
  if (p.pos_noise.On())
    for (int k = 0; k < 3; ++k) rd.position[k] += robot.sensor_rng.Uniform(p.pos_noise.lo, p.pos_noise.hi);
  if (p.angle_noise.On() || p.axis_noise.On()) {
    // Through angle-axis, as ARGoS: angle += u, axis += u per component (not re-normalised).
    double angle = 2 * std::acos(std::clamp(rd.quat_w, -1.0, 1.0));
    double s = std::sqrt(1 - rd.quat_w * rd.quat_w);
    Vec3 axis = s > 1e-12 ? Vec3(rd.quat_x / s, rd.quat_y / s, rd.quat_z / s) : Vec3(0, 0, 1);
    if (p.angle_noise.On()) angle += robot.sensor_rng.Uniform(p.angle_noise.lo, p.angle_noise.hi);
    if (p.axis_noise.On())
      for (int k = 0; k < 3; ++k) axis[k] += robot.sensor_rng.Uniform(p.axis_noise.lo, p.axis_noise.hi);
    rd.quat_w = std::cos(angle / 2);
    rd.quat_x = axis.x() * std::sin(angle / 2);
    rd.quat_y = axis.y() * std::sin(angle / 2);
    rd.quat_z = axis.z() * std::sin(angle / 2);
  }
}

}  // namespace essaim
