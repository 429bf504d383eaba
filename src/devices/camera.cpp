// Colored-blob omnidirectional camera, rot_z_only (as ARGoS's). Looks up the lit LEDs of
// the LED field's grid in the square |dx|, |dy| < z_cam·tan(aperture) around the robot.
// ARGoS sees an LED whose height above the camera is less than the camera's own height
// (LED z − camera z < camera z: up to twice the camera's height, 0.577 m on the floor).
//
// Occlusion in 3D, by ARGoS's ray rule: the segment from the camera (0.2887 m above the
// robot) to the LED against every shape's heights where it enters the shape or crosses its
// top (camera_occlusion.cpp), the camera robot's own shapes excepted. So an LED behind a low
// box or another robot may be seen over it, a light inside a wall is hidden, and a robot's
// own body and gripper disc hide its LEDs on the far side: what ARGoS shows, measured on
// every blob of tests/fidelity's scenes.
#include <algorithm>
#include <cmath>

#include "devices/devices.h"

namespace essaim {

void SenseCamera(const SenseContext& ctx, const DeviceConfig& cfg, const RobotDef& def, RobotState& robot) {
  Readings& rd = robot.rd;
  rd.blobs.clear();
  if (!robot.camera_enabled) return;
  const Media& media = ctx.media;
  const int self = robot.index;
  if (media.camera_medium.empty() || media.camera_medium[self] < 0 || media.leds.empty()) return;
  const int medium = media.camera_medium[self];
  const Pose2 pose = ctx.physics.RobotPose(self);
  const double half = footbot::kCameraElevation * std::tan(def.camera_aperture);
  if (!(half > 0)) return;
  const double camera_z = def.z + footbot::kCameraElevation;
  const double noise = cfg.params.noise_std_dev;
  const Vec3 eye(pose.x, pose.y, camera_z);
  media.led_grid.ForEachInBox(pose.x - half, pose.y - half, pose.x + half, pose.y + half, [&](int li) {
    const LitLed& led = media.leds[li];
    if (led.robot == self || led.medium != medium) return;
    Vec2 rel(led.pos.x() - pose.x, led.pos.y() - pose.y);
    if (std::abs(rel.x()) >= half || std::abs(rel.y()) >= half || !(led.pos.z() - camera_z < camera_z)) return;
    // An LED on (or above) the top of its own box or cylinder is not hidden by it: where it
    // sits exactly on the top, ARGoS's answer turns on the rounding of one plane crossing.
    const int carrier = led.obstacle >= 0 && led.pos.z() >= media.obstacle_top[led.obstacle] ? led.obstacle : -1;
    if (CameraRayBlocked(ctx.model, media, eye, led.pos, self, carrier)) return;
    Blob b;  // holds the planar vector until noise and conversion below
    b.distance = rel.x();
    b.angle = rel.y();
    b.color = led.color;
    b.led = li;
    rd.blobs.push_back(b);
  });
  // Cells come in grid order; report (and draw noise) in LED order (robots by index, LEDs
  // 1..13, then box and cylinder LEDs, then lights), independent of the grid geometry.
  std::sort(rd.blobs.begin(), rd.blobs.end(), [](const Blob& a, const Blob& b) { return a.led < b.led; });
  for (Blob& b : rd.blobs) {
    Vec2 rel(b.distance, b.angle);
    if (noise > 0) {
      // A vector of length |rel|·N(0, sd) in a uniform direction.
      const double len = rel.norm() * robot.sensor_rng.Gaussian(noise);
      const double dir = robot.sensor_rng.Uniform(0, kTwoPi);
      rel += Vec2(len * std::cos(dir), len * std::sin(dir));
    }
    b.distance = rel.norm() * 100.0;
    b.angle = WrapSigned(std::atan2(rel.y(), rel.x()) - pose.yaw);
  }
}

}  // namespace essaim
