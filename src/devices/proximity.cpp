// Foot-bot proximity sensor: 24 rays of 0.1 m from the body surface at
// 7.5° + 15°·k, 6 cm above the floor; value 0.0100527 / (d + 0.000163144), 1 when closer
// than 0.009889556 m, 0 without a hit; uniform noise added to every sensor (hit or not),
// then clamped to [0, 1]. The shapes within reach are gathered once per tick, then each
// ray is tested against that short list with Box2D's shape ray casts.
#include <algorithm>
#include <cmath>

#include "devices/devices.h"

namespace essaim {

namespace {
constexpr double kRange = 0.1;               // m, ray length
constexpr double kSaturation = 0.009889556;  // m: closer reads 1
constexpr double kNumerator = 0.0100527;
constexpr double kOffset = 0.000163144;

struct Ring {
  double angle[kRingSensorCount];  // signed-normalized, robot frame
  double cos[kRingSensorCount], sin[kRingSensorCount];
};

Ring MakeRing() {
  Ring r{};
  for (int k = 0; k < kRingSensorCount; ++k) {
    r.angle[k] = WrapSigned(kPi / 24 + k * kPi / 12);
    r.cos[k] = std::cos(r.angle[k]);
    r.sin[k] = std::sin(r.angle[k]);
  }
  return r;
}
const Ring kRing = MakeRing();
}  // namespace

double RingSensorAngle(int k) { return kRing.angle[k]; }

double ProximityValue(double d) {
  if (d < kSaturation) return 1.0;
  return kNumerator / (d + kOffset);
}

void SenseProximity(const DeviceConfig& cfg, RobotState& robot, const PhysicsWorld& physics) {
  const Pose2 p = physics.RobotPose(robot.index);
  const double cy = std::cos(p.yaw), sy = std::sin(p.yaw);
  const double noise = cfg.params.noise_level;
  double* out = robot.rd.proximity;
  // One tree query for the 24 rays; most robots have nothing within reach.
  RayCandidates& near_shapes = robot.proximity_candidates;
  physics.GatherRayCandidates({p.x, p.y}, footbot::kRadius + kRange, footbot::kProximityElevation, robot.index,
                              &near_shapes);
  const bool near = !near_shapes.items.empty();
  for (int k = 0; k < kRingSensorCount; ++k) {
    if (!near) {
      double v = noise > 0 ? robot.sensor_rng.Uniform(-noise, noise) : 0.0;
      out[k] = std::clamp(v, 0.0, 1.0);
      continue;
    }
    // Direction = yaw + θ_k, by the angle-sum identity on the precomputed ring.
    const double c = cy * kRing.cos[k] - sy * kRing.sin[k];
    const double s = sy * kRing.cos[k] + cy * kRing.sin[k];
    const Vec2 from(p.x + footbot::kRadius * c, p.y + footbot::kRadius * s);
    const Vec2 to(from.x() + kRange * c, from.y() + kRange * s);
    const RayHit hit = physics.CastRay(near_shapes, from, to);
    double v = hit.Hit() ? ProximityValue(hit.distance) : 0.0;
    if (noise > 0) v += robot.sensor_rng.Uniform(-noise, noise);
    out[k] = std::clamp(v, 0.0, 1.0);
  }
}

}  // namespace essaim
