// What hides a lit LED from a camera: one planar ray from the camera robot to the LED,
// decided by exact circle and box tests on grids of the bodies and obstacles (what
// PhysicsWorld::CastRay would answer, without walking Box2D's tree per ray).
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

bool CameraRayBlocked(const Model& model, const Media& m, const Vec2& a, const Vec2& b, double z, int exclude_robot,
                      int skip_obstacle) {
  const Vec2 lo = a.cwiseMin(b), hi = a.cwiseMax(b);
  if (z >= 0 && z <= footbot::kHeight) {  // robots reach this height (PhysicsWorld::CastRay)
    const double r = footbot::kRadius;
    auto hides = [&](int j) { return j != exclude_robot && CircleEntry(a, b, m.body_xy[j], r) <= 1; };
    if (m.camera_body_grid.AnyInBox(lo.x() - r, lo.y() - r, hi.x() + r, hi.y() + r, hides)) return true;
  }
  if (m.obstacle_xy.empty()) return false;
  // Obstacles sit in every cell they overlap.
  return m.camera_obstacle_grid.AnyInBox(lo.x(), lo.y(), hi.x(), hi.y(), [&](int k) {
    const ObstacleDef& o = model.obstacles[k];
    if (k == skip_obstacle || z < o.z || z > o.z + o.height) return false;
    return ObstacleEntry(o, m, k, a, b) <= 1;
  });
}

}  // namespace essaim
