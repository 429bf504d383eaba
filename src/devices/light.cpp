// Foot-bot light sensor, rot_z_only. For every <light> with intensity > 0
// that a ray from the robot origin (floor level) to the light does not meet: d = |light −
// origin| / intensity, base = exp(−2d) (0 beyond d = 2.5); the 13 ring sensors around the
// light's bearing get base·(1 − 2Δ/π), Δ = the sensor's angular distance to the bearing
// (0 past π/2). Contributions add up; then uniform noise and a clamp to [0, 1].
//
// Occlusion follows ARGoS's 3D ray: it rises from z = robot z at the origin to the
// light's z, and a shape blocks it only where the ray's height at the hit lies within the
// shape's height. CastRay takes one height, so the ray is walked: cast at the current
// height (shapes lower than that can never be hit further on, the ray only rises); if
// the closest hit passes over that shape, continue from there at the new height.
#include <algorithm>
#include <cmath>

#include "devices/devices.h"

namespace essaim {

namespace {
constexpr double kMaxDistance = 2.5;  // intensity-scaled m; beyond reads 0
constexpr int kSpread = 6;            // sensors each side of the nearest one
constexpr int kMaxWalk = 32;          // shapes passed over before giving up (= occluded)

/// Vertical extent of what a ray hit.
void HitExtent(const Model& model, const RayHit& hit, double* bottom, double* top) {
  if (hit.kind == BodyKind::Obstacle) {
    const ObstacleDef& o = model.obstacles[hit.index];
    *bottom = o.z;
    *top = o.z + o.height;
  } else {
    *bottom = 0;  // robots stand on the floor (PhysicsWorld::CastRay assumes so too)
    *top = footbot::kHeight;
  }
}
}  // namespace

bool LightOccluded(const Model& model, const PhysicsWorld& physics, int self, const Vec3& from, const Vec3& light) {
  const Vec2 a(from.x(), from.y()), b(light.x(), light.y());
  const double length = (b - a).norm();
  if (length <= 0) return false;  // straight above: the planar query is a point, nothing in the way
  // A ray that does not rise is checked at its start height (lights below a robot's
  // origin do not occur in practice).
  const double rise = std::max(0.0, light.z() - from.z());
  Vec2 start = a;
  double travelled = 0;  // planar m from `a` to `start`
  double z = from.z();
  for (int i = 0; i < kMaxWalk; ++i) {
    const RayHit hit = physics.CastRay(start, b, z, self);
    if (!hit.Hit()) return false;
    travelled += hit.distance;
    const double zhit = from.z() + rise * std::min(1.0, travelled / length);
    double bottom, top;
    HitExtent(model, hit, &bottom, &top);
    if (zhit <= top && zhit >= bottom) return true;
    // Passed over it: shapes not reaching zhit can no longer be hit; that includes this one.
    start = hit.point;
    z = zhit;
  }
  return true;
}

void SenseLight(const DeviceConfig& cfg, const Model& model, const RobotDef& def, RobotState& robot,
                const PhysicsWorld& physics) {
  double* out = robot.rd.light;
  std::fill(out, out + kRingSensorCount, 0.0);
  const Pose2 p = physics.RobotPose(robot.index);
  const Vec3 origin(p.x, p.y, def.z);
  for (const LightDef& l : model.lights) {
    if (l.intensity <= 0) continue;
    const Vec3 v = l.position - origin;
    const double d = v.norm() / l.intensity;
    // The reading would be 0 whatever the ray says: skip the ray (ARGoS casts it).
    if (d > kMaxDistance) continue;
    if (LightOccluded(model, physics, robot.index, origin, l.position)) continue;
    const double base = std::exp(-2 * d);
    const double bearing = WrapSigned(std::atan2(v.y(), v.x()) - p.yaw);
    // Nearest sensor: θ_k = π/24 + kπ/12.
    const int nearest = static_cast<int>(std::lround((bearing - kPi / 24) / (kPi / 12)));
    for (int off = -kSpread; off <= kSpread; ++off) {
      const int k = ((nearest + off) % kRingSensorCount + kRingSensorCount) % kRingSensorCount;
      const double delta = std::fabs(WrapSigned(bearing - RingSensorAngle(k)));
      if (delta < kPi / 2) out[k] += base * (1 - 2 * delta / kPi);
    }
  }
  const double noise = cfg.params.noise_level;
  for (int k = 0; k < kRingSensorCount; ++k) {
    if (noise > 0) out[k] += robot.sensor_rng.Uniform(-noise, noise);
    out[k] = std::clamp(out[k], 0.0, 1.0);
  }
}

}  // namespace essaim
