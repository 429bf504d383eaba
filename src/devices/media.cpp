// Media stage: after physics, before any robot senses. Reads the bodies' and obstacles'
// poses once, then routes range and bearing (rab_routing.cpp), lists the lit LEDs
// (led_field.cpp) and files what may hide them from cameras (camera_occlusion.cpp).
// Every buffer is sized by InitMedia; a tick allocates nothing.
#include "devices/media.h"

#include <algorithm>
#include <cmath>

namespace essaim {

double ObstacleEntry(const ObstacleDef& o, const Media& m, int k, const Vec2& a, const Vec2& b) {
  return o.kind == ShapeKind::Cylinder ? CircleEntry(a, b, m.obstacle_xy[k], o.radius)
                                       : BoxEntry(a, b, m.obstacle_xy[k], m.obstacle_cs[k], o.size_x / 2, o.size_y / 2);
}

bool ObstacleSpan(const ObstacleDef& o, const Media& m, int k, const Vec2& a, const Vec2& b, double* t0, double* t1) {
  return o.kind == ShapeKind::Cylinder
             ? CircleSpan(a, b, m.obstacle_xy[k], o.radius, t0, t1)
             : BoxSpan(a, b, m.obstacle_xy[k], m.obstacle_cs[k], o.size_x / 2, o.size_y / 2, t0, t1);
}

void CoverObstacles(const Vec2& lo, const Vec2& hi, double cell, double slack_cells, const Media& m, UniformGrid* g) {
  const size_t obstacles = m.obstacle_radius.size();
  g->CoverBox(lo, hi, cell, 4 * obstacles + 64);
  size_t entries = 0;
  for (double r : m.obstacle_radius) entries += g->DiscCells(r + slack_cells * g->CellSize());
  g->Reserve(entries, obstacles);
}

namespace {
/// Per-body buffers, and what of each obstacle does not change: its top, its bounding circle.
void InitBodies(const Model& model, Media* m) {
  m->body_xy.assign(model.robots.size(), Vec2::Zero());
  m->gripper_xy.assign(model.robots.size(), Vec2::Zero());
  const size_t obstacles = model.obstacles.size();
  m->obstacle_xy.assign(obstacles, Vec2::Zero());
  m->obstacle_cs.assign(obstacles, Vec2(1, 0));
  m->obstacle_radius.assign(obstacles, 0);
  m->obstacle_lo.assign(obstacles, Vec2::Zero());
  m->obstacle_hi.assign(obstacles, Vec2::Zero());
  m->obstacle_top.assign(obstacles, 0);
  for (size_t o = 0; o < obstacles; ++o) {
    const ObstacleDef& def = model.obstacles[o];
    m->obstacle_top[o] = def.z + def.height;
    m->obstacle_radius[o] =
        (def.kind == ShapeKind::Cylinder ? def.radius : 0.5 * std::hypot(def.size_x, def.size_y)) + 1e-6;
  }
}

/// This tick's poses of every body and obstacle, and each obstacle's bounding box.
void ReadPoses(const Model& model, const PhysicsWorld& physics, Media* m) {
  const int n = static_cast<int>(m->body_xy.size());
  for (int i = 0; i < n; ++i) {
    const Pose2 p = physics.RobotPose(i);
    m->body_xy[i] = Vec2(p.x, p.y);
    m->gripper_xy[i] = physics.GripperDiscPoint(i);
    m->rab_pos[i] = Vec3(p.x, p.y, model.robots[i].z + footbot::kRabElevation);
    m->rab_yaw[i] = p.yaw;
  }
  for (size_t k = 0; k < m->obstacle_xy.size(); ++k) {
    const Pose2 p = physics.ObstaclePose(static_cast<int>(k));
    m->obstacle_xy[k] = Vec2(p.x, p.y);
    m->obstacle_cs[k] = Vec2(std::cos(p.yaw), std::sin(p.yaw));
    const ObstacleDef& o = model.obstacles[k];
    const Vec2& cs = m->obstacle_cs[k];
    const Vec2 half = o.kind == ShapeKind::Cylinder
                          ? Vec2(o.radius, o.radius)
                          : Vec2(std::abs(cs.x()) * o.size_x / 2 + std::abs(cs.y()) * o.size_y / 2,
                                 std::abs(cs.y()) * o.size_x / 2 + std::abs(cs.x()) * o.size_y / 2);
    // Rounding in BoxEntry/CircleEntry is ~1e-16 of the coordinates: 1e-9 is ample.
    const Vec2 margin = (half + m->obstacle_xy[k].cwiseAbs()) * 1e-9 + Vec2(1e-9, 1e-9);
    m->obstacle_lo[k] = m->obstacle_xy[k] - half - margin;
    m->obstacle_hi[k] = m->obstacle_xy[k] + half + margin;
  }
}
}  // namespace

void InitMedia(const Model& model, Media* m) {
  InitBodies(model, m);
  InitRabRouting(model, m);
  InitCameraOcclusion(model, m);
  InitLedField(model, m);  // its grid's cells follow the cameras' reach
  m->ready = true;
}

void UpdateMedia(const Model& model, const PhysicsWorld& physics, const RobotStates& robots, Media* m,
                 const SlotRunner& runner) {
  if (!m->ready) InitMedia(model, m);
  if (m->rab_devices >= 2 || m->any_camera) ReadPoses(model, physics, m);
  RouteRab(model, robots, m, runner);
  UpdateLedField(model, physics, robots, m);
  FileCameraOccluders(m);
}

}  // namespace essaim
