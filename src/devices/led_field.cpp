// The LED field: every lit LED of the tick (robots' rings and beacons, box and cylinder
// LEDs, <light>s) with its medium, bucketed in a grid that the cameras query. Listed only
// when some camera looks.
#include <cmath>

#include "devices/media.h"

namespace essaim {

Vec3 FootBotLedPosition(const Pose2& pose, double z, double turret, int i) {
  constexpr double kRingRadius = 0.090036758;  // body radius + 5 mm (ARGoS's foot-bot LED ring)
  constexpr double kRingElevation = 0.085;
  constexpr double kBeaconElevation = 0.174249733;
  if (i >= 12) return Vec3(pose.x, pose.y, z + kBeaconElevation);
  double a = pose.yaw + turret + DegToRad(15.0 + 30.0 * i);
  return Vec3(pose.x + kRingRadius * std::cos(a), pose.y + kRingRadius * std::sin(a), z + kRingElevation);
}

namespace {
/// ARGoS compares colours with alpha: only (0,0,0,255) is "black", i.e. off.
bool LedOff(const Color& c) { return c == Color(); }

void ListRobotLeds(const Model& model, const PhysicsWorld& physics, const RobotStates& robots, Media* m) {
  for (int i = 0; i < static_cast<int>(robots.size()); ++i) {
    if (m->led_medium[i] < 0 || !robots[i].alive) continue;
    const RobotState& r = robots[i];
    Pose2 pose;
    bool posed = false;
    for (int j = 0; j < footbot::kLedCount; ++j) {
      if (LedOff(r.leds[j])) continue;
      if (!posed) pose = physics.RobotPose(i), posed = true;
      LitLed l;
      l.pos = FootBotLedPosition(pose, model.robots[i].z, r.turret_rotation, j);
      l.color = r.leds[j];
      l.robot = i;
      l.medium = m->led_medium[i];
      m->leds.push_back(l);
    }
  }
}

void ListObstacleLeds(const Model& model, Media* m) {
  for (size_t o = 0; o < model.obstacles.size(); ++o) {
    if (m->obstacle_led_medium[o] < 0) continue;
    const ObstacleDef& def = model.obstacles[o];
    const Vec2& xy = m->obstacle_xy[o];
    const Vec2& cs = m->obstacle_cs[o];
    for (const LedDef& led : def.leds) {
      if (LedOff(led.color)) continue;
      LitLed l;
      l.pos = Vec3(xy.x() + cs.x() * led.offset.x() - cs.y() * led.offset.y(),
                   xy.y() + cs.y() * led.offset.x() + cs.x() * led.offset.y(), def.z + led.offset.z());
      l.color = led.color;
      l.obstacle = static_cast<int>(o);
      l.medium = m->obstacle_led_medium[o];
      m->leds.push_back(l);
    }
  }
}

void ListLights(const Model& model, Media* m) {
  for (size_t k = 0; k < model.lights.size(); ++k) {
    if (m->light_medium[k] < 0 || LedOff(model.lights[k].color)) continue;
    LitLed l;
    l.pos = model.lights[k].position;
    l.color = model.lights[k].color;
    l.medium = m->light_medium[k];
    m->leds.push_back(l);
  }
}
}  // namespace

void InitLedField(const Model& model, Media* m) {
  const size_t n = model.robots.size();
  size_t capacity = 0;
  m->led_medium.assign(n, -1);
  for (size_t i = 0; i < n; ++i) {
    const DeviceConfig* d = model.controllers[model.robots[i].controller].Find(DeviceType::LedsActuator);
    if (d) m->led_medium[i] = MediumIndex(model.led_media, d->Attr("medium"));
    if (m->led_medium[i] >= 0) capacity += footbot::kLedCount;
  }
  m->obstacle_led_medium.assign(model.obstacles.size(), -1);
  for (size_t o = 0; o < model.obstacles.size(); ++o) {
    const ObstacleDef& def = model.obstacles[o];
    if (def.leds.empty()) continue;
    m->obstacle_led_medium[o] = MediumIndex(model.led_media, def.led_medium);
    capacity += def.leds.size();
  }
  m->light_medium.assign(model.lights.size(), -1);
  for (size_t k = 0; k < model.lights.size(); ++k)
    m->light_medium[k] = MediumIndex(model.led_media, model.lights[k].medium);
  capacity += model.lights.size();
  m->leds.clear();
  m->leds.reserve(capacity);
  if (!m->any_camera) return;
  // Cells of about a camera's half range, so that a camera's square touches at most 3x3.
  double h = m->camera_half_range;
  if (!(h > 0) || !std::isfinite(h)) h = 1e9;  // aperture >= 90°: the whole arena
  m->led_grid.CoverBox(model.arena.Min(), model.arena.Max(), h, 4 * capacity + 64);
  m->led_grid.Reserve(capacity, capacity);
}

void UpdateLedField(const Model& model, const PhysicsWorld& physics, const RobotStates& robots, Media* m) {
  m->leds.clear();
  if (!m->any_camera) return;  // nobody looks: skip the index entirely
  ListRobotLeds(model, physics, robots, m);
  ListObstacleLeds(model, m);
  ListLights(model, m);
  m->led_grid.FilePoints(static_cast<int>(m->leds.size()), [&](int k) { return Vec2(m->leds[k].pos.head<2>()); });
}

}  // namespace essaim
