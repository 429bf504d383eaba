// Foot-bot ground sensors, rot_z_only: the floor's grey level under points
// fixed in the robot frame. Base ground: 8 points, grey + noise, then binary (< 0.5 → 0,
// else 1). Motor ground: 4 points, grey + noise, clamped to [0, 1]. The floor is the
// World's raster (image or loop-function floor_color), read through FloorRaster::Grey.
#include <algorithm>
#include <cmath>

#include "devices/devices.h"

namespace essaim {

// Offsets in cm, robot frame (x forward, y left), as ARGoS stores and shows them; the
// sensor point is robot position + 0.01 · (offset rotated by the yaw).
const double kBaseGroundOffsets[kBaseGroundCount][2] = {
    {8.0, 0.0}, {4.2, 6.5}, {0.0, 8.0}, {-4.2, 6.5}, {-8.0, 0.0}, {-4.2, -6.5}, {0.0, -8.0}, {4.2, -6.5},
};
const double kMotorGroundOffsets[kMotorGroundCount][2] = {
    {6.3, 1.16},
    {-6.3, 1.16},
    {-6.3, -1.16},
    {6.3, -1.16},
};

namespace {
template <int N>
void Sample(const double (&offsets)[N][2], const DeviceConfig& cfg, RobotState& robot, const PhysicsWorld& physics,
            const FloorRaster& floor, bool binary, double* out) {
  const Pose2 p = physics.RobotPose(robot.index);
  const double c = std::cos(p.yaw), s = std::sin(p.yaw);
  const double noise = cfg.params.noise_level;
  for (int i = 0; i < N; ++i) {
    const double ox = offsets[i][0], oy = offsets[i][1];
    double v = floor.Grey(p.x + (c * ox - s * oy) * 0.01, p.y + (s * ox + c * oy) * 0.01);
    if (noise > 0) v += robot.sensor_rng.Uniform(-noise, noise);
    out[i] = binary ? (v < 0.5 ? 0.0 : 1.0) : std::clamp(v, 0.0, 1.0);
  }
}
}  // namespace

void SenseBaseGround(const DeviceConfig& cfg, RobotState& robot, const PhysicsWorld& physics,
                     const FloorRaster& floor) {
  Sample(kBaseGroundOffsets, cfg, robot, physics, floor, true, robot.rd.base_ground);
}

void SenseMotorGround(const DeviceConfig& cfg, RobotState& robot, const PhysicsWorld& physics,
                      const FloorRaster& floor) {
  Sample(kMotorGroundOffsets, cfg, robot, physics, floor, false, robot.rd.motor_ground);
}

}  // namespace essaim
