// What hides a lit LED from a camera: the segment from the camera to the LED, in 3D, meets
// a shape's volume (CameraRayBlocked), decided by exact circle and box tests on grids of
// the bodies, their gripper discs and the obstacles.
#include <algorithm>
#include <cmath>

#include "devices/media.h"

namespace essaim {

void InitCameraOcclusion(const Model& model, Media* m) {
  const size_t n = model.robots.size();
  m->camera_medium.assign(n, -1);
  m->any_camera = false;
  m->camera_half_range = 0;
  for (size_t i = 0; i < n; ++i) {
    const DeviceConfig* d = model.controllers[model.robots[i].controller].Find(DeviceType::CameraSensor);
    if (!d) continue;
    m->camera_medium[i] = MediumIndex(model.led_media, d->Attr("medium"));
    if (m->camera_medium[i] < 0) continue;
    m->any_camera = true;
    m->camera_half_range =
        std::max(m->camera_half_range, footbot::kCameraElevation * std::tan(model.robots[i].camera_aperture));
  }
  if (!m->any_camera) return;
  double h = m->camera_half_range;
  if (!(h > 0) || !std::isfinite(h)) h = 1e9;  // aperture >= 90°: the whole arena
  // Occlusion rays are at most h·sqrt(2) long: cells of about h/2 keep the cells a ray's
  // box touches few and small.
  const Vec2 lo = model.arena.Min(), hi = model.arena.Max();
  m->camera_body_grid.CoverBox(lo, hi, h / 2, 4 * n + 64);
  m->camera_body_grid.Reserve(n, n);
  CoverObstacles(lo, hi, h / 2, 0, *m, &m->camera_obstacle_grid);
}

void FileCameraOccluders(Media* m) {
  if (!m->any_camera) return;
  m->camera_body_grid.FilePoints(static_cast<int>(m->body_xy.size()), [&](int i) { return m->body_xy[i]; });
  if (m->obstacle_xy.empty()) return;
  // Each obstacle over the cells of its bounding disc's box.
  m->camera_obstacle_grid.FileBoxes(
      static_cast<int>(m->obstacle_xy.size()),
      [&](int k) { return Vec2(m->obstacle_xy[k].array() - m->obstacle_radius[k]); },
      [&](int k) { return Vec2(m->obstacle_xy[k].array() + m->obstacle_radius[k]); });
}

namespace {
/// Whether a shape hides the 3D segment from -> to, by the rule of ARGoS's ray queries: the
/// segment's ground projection enters the footprint at fraction t0 (from outside: one that
/// starts inside meets nothing) and leaves it at t1; it hits where it enters if its height
/// there is within the shape's [bottom, top]; if it enters above the top, where it crosses the
/// top's plane, if that lies over the footprint (before t1). Bottom faces are not tested,
/// as in ARGoS. A light inside a wall is so hidden, and a robot's far-side LEDs by its top.
bool HidesLikeArgos(double t0, double t1, const Vec3& from, const Vec3& to, double bottom, double top) {
  if (!(t0 > 0)) return false;
  const double dz = to.z() - from.z();
  const double z0 = from.z() + dz * t0;
  if (z0 >= bottom && z0 <= top) return true;
  if (z0 < top || !(dz < 0)) return false;  // below the bottom, or rising away from the top
  return (top - from.z()) / dz <= t1;
}
}  // namespace

bool CameraRayBlocked(const Model& model, const Media& m, const Vec3& from, const Vec3& to, int exclude_robot,
                      int skip_obstacle) {
  const Vec2 a = from.head<2>(), b = to.head<2>();
  const Vec2 lo = a.cwiseMin(b), hi = a.cwiseMax(b);
  double t0, t1;
  // A gripper disc lies within the body radius plus its own of its robot's centre.
  const double reach = footbot::kRadius + kGripperRadius;
  auto robot_hides = [&](int j) {
    if (j == exclude_robot) return false;
    const double bottom = model.robots[j].z, top = bottom + footbot::kHeight;
    return (CircleSpan(a, b, m.body_xy[j], footbot::kRadius, &t0, &t1) &&
            HidesLikeArgos(t0, t1, from, to, bottom, top)) ||
           (CircleSpan(a, b, m.gripper_xy[j], kGripperRadius, &t0, &t1) &&
            HidesLikeArgos(t0, t1, from, to, bottom, top));
  };
  if (m.camera_body_grid.AnyInBox(lo.x() - reach, lo.y() - reach, hi.x() + reach, hi.y() + reach, robot_hides))
    return true;
  if (m.obstacle_xy.empty()) return false;
  // Obstacles sit in every cell they overlap.
  return m.camera_obstacle_grid.AnyInBox(lo.x(), lo.y(), hi.x(), hi.y(), [&](int k) {
    const ObstacleDef& o = model.obstacles[k];
    return k != skip_obstacle && ObstacleSpan(o, m, k, a, b, &t0, &t1) &&
           HidesLikeArgos(t0, t1, from, to, o.z, o.z + o.height);
  });
}

}  // namespace essaim
