#include "devices/entity_store.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/strings.h"
#include "devices/devices.h"
#include "model/distribute.h"
#include "model/limits.h"

namespace essaim {

namespace {
constexpr const char* kKindNames[] = {"foot-bot", "box", "cylinder", "light"};

EntityKind ObstacleKind(const ObstacleDef& o) {
  return o.kind == ShapeKind::Box ? EntityKind::Box : EntityKind::Cylinder;
}
}  // namespace

const char* EntityKindName(EntityKind kind) { return kKindNames[static_cast<int>(kind)]; }

bool ParseEntityKind(const char* name, EntityKind* kind) {
  for (int k = 0; k < 4; ++k)
    if (!std::strcmp(name, kKindNames[k])) return *kind = static_cast<EntityKind>(k), true;
  return false;
}

void EntityStore::Init(Model* scene, PhysicsWorld* physics, RobotStates* robots) {
  scene_ = scene;
  physics_ = physics;
  robots_ = robots;
  order_.clear();
  added_.clear();
  obstacle_serial_.clear(), light_serial_.clear(), obstacle_index_.clear(), light_index_.clear();
  ids_.clear();
  for (const RobotDef& r : scene->robots) AddId(r.id);
  for (const ObstacleDef& o : scene->obstacles) AddId(o.id);
  for (const LightDef& l : scene->lights) AddId(l.id);
  for (size_t i = 0; i < scene->robots.size(); ++i) order_.push_back({EntityKind::FootBot, static_cast<uint32_t>(i)});
  for (size_t i = 0; i < scene->obstacles.size(); ++i) {
    order_.push_back({ObstacleKind(scene->obstacles[i]), static_cast<uint32_t>(i)});
    obstacle_serial_.push_back(static_cast<uint32_t>(i));
    obstacle_index_.push_back(static_cast<int>(i));
  }
  for (size_t i = 0; i < scene->lights.size(); ++i) {
    order_.push_back({EntityKind::Light, static_cast<uint32_t>(i)});
    light_serial_.push_back(static_cast<uint32_t>(i));
    light_index_.push_back(static_cast<int>(i));
  }
  ClearChanged();
}

int EntityStore::IndexOf(const EntityRef& e) const {
  switch (e.kind) {
    case EntityKind::FootBot:
      return e.serial < scene_->robots.size() ? static_cast<int>(e.serial) : -1;
    case EntityKind::Light:
      return e.serial < light_index_.size() ? light_index_[e.serial] : -1;
    default:
      return e.serial < obstacle_index_.size() ? obstacle_index_[e.serial] : -1;
  }
}

bool EntityStore::HasId(const std::string& id) const { return ids_.count(id) > 0; }

void EntityStore::RemoveId(const std::string& id) {
  auto it = ids_.find(id);
  if (it != ids_.end() && --it->second == 0) ids_.erase(it);
}

EntityRef EntityStore::AddObstacle(const ObstacleDef& def) {
  const uint32_t serial = static_cast<uint32_t>(obstacle_index_.size());
  const int index = physics_->AddObstacle(def);
  scene_->obstacles.push_back(def);
  AddId(def.id);
  obstacle_serial_.push_back(serial);
  obstacle_index_.push_back(index);
  EntityRef e{ObstacleKind(def), serial};
  order_.push_back(e);
  added_.push_back(e);
  MarkChanged(true);
  return e;
}

int EntityStore::ControllerIndex(const std::string& id) const {
  for (size_t i = 0; i < scene_->controllers.size(); ++i)
    if (scene_->controllers[i].id == id) return static_cast<int>(i);
  return -1;
}

std::string EntityStore::RobotProblemNow(const RobotDef& def) const {
  if (!joiner_) return "foot-bots can be added from the loop functions' init() on";
  if (HasId(def.id)) return "id '" + def.id + "' is already used";
  if (ControllerIndex(def.controller_id) < 0) return "no controller with id '" + def.controller_id + "'";
  const Vec2 p(def.pose.x, def.pose.y), lo = scene_->arena.Min(), hi = scene_->arena.Max();
  if (!(p.array() >= lo.array()).all() || !(p.array() <= hi.array()).all())
    return "position (" + FormatDouble(p.x()) + ", " + FormatDouble(p.y()) + ") is outside the arena";
  if (!std::isfinite(def.pose.yaw) || !std::isfinite(def.z)) return "its orientation and height must be finite";
  // C++ loop functions hand these over unchecked: a NaN or infinite range would size the
  // media's grids from it.
  if (!(def.rab_range >= 0) || !std::isfinite(def.rab_range)) return "rab_range must be a finite number >= 0";
  if (!(def.camera_aperture > 0) || !std::isfinite(def.camera_aperture))
    return "the omnidirectional camera's aperture must be a finite angle > 0";
  return RoomProblem(true);
}

bool EntityStore::AddRobot(const RobotDef& def, EntityRef* added, std::string* error) {
  *error = RobotProblemNow(def);
  if (!error->empty()) return false;
  scene_->robots.push_back(def);
  AddId(def.id);
  RobotDef& bound = scene_->robots.back();  // bound to its controller, as the loader binds
  bound.controller = ControllerIndex(def.controller_id);
  bound.params = scene_->controllers[bound.controller].params;
  const int index = physics_->AddRobot(bound);
  robots_->emplace_back();
  InitRobotState(*scene_, index, robots_->back(), *physics_);
  if (!joiner_->Join(index, error)) {
    robots_->pop_back();
    physics_->RemoveLastRobot();
    RemoveId(def.id);
    scene_->robots.pop_back();
    return false;
  }
  *added = {EntityKind::FootBot, static_cast<uint32_t>(index)};
  order_.push_back(*added);
  added_.push_back(*added);
  MarkChanged(true);  // the media size their per-robot buffers anew
  return true;
}

EntityRef EntityStore::AddLight(const LightDef& def) {
  const uint32_t serial = static_cast<uint32_t>(light_index_.size());
  light_serial_.push_back(serial);
  light_index_.push_back(static_cast<int>(scene_->lights.size()));
  scene_->lights.push_back(def);
  AddId(def.id);
  EntityRef e{EntityKind::Light, serial};
  order_.push_back(e);
  added_.push_back(e);
  MarkChanged(true);
  return e;
}

bool EntityStore::Remove(const EntityRef& e) {
  const int index = IndexOf(e);
  if (index < 0 || e.kind == EntityKind::FootBot) return false;
  // Compact: sensors then loop over live entities only, with no "removed" test anywhere.
  const bool light = e.kind == EntityKind::Light;
  auto& serials = light ? light_serial_ : obstacle_serial_;
  auto& indices = light ? light_index_ : obstacle_index_;
  RemoveId(IdOf(e));
  if (light) {
    scene_->lights.erase(scene_->lights.begin() + index);
  } else {
    physics_->RemoveObstacle(index);
    scene_->obstacles.erase(scene_->obstacles.begin() + index);
  }
  serials.erase(serials.begin() + index);
  indices[e.serial] = -1;
  for (size_t k = index; k < serials.size(); ++k) indices[serials[k]] = static_cast<int>(k);
  const bool is_light = light;
  order_.erase(std::find_if(order_.begin(), order_.end(), [&](const EntityRef& o) {
    return o.serial == e.serial && (o.kind == EntityKind::Light) == is_light && o.kind != EntityKind::FootBot;
  }));
  MarkChanged(true);
  return true;
}

void EntityStore::SetObstaclePose(int index, const Pose2& pose) {
  physics_->SetObstaclePose(index, pose);
  scene_->obstacles[index].pose = pose;
  MarkChanged(false);
}

const std::string& EntityStore::IdOf(const EntityRef& e) const {
  const int i = IndexOf(e);
  if (e.kind == EntityKind::FootBot) return scene_->robots[i].id;
  if (e.kind == EntityKind::Light) return scene_->lights[i].id;
  return scene_->obstacles[i].id;
}

size_t EntityStore::Count() const { return scene_->robots.size() + scene_->obstacles.size() + scene_->lights.size(); }

namespace {
bool IsObstacle(const EntityRef& e) { return e.kind == EntityKind::Box || e.kind == EntityKind::Cylinder; }
}  // namespace

Vec3 EntityStore::Position(const EntityRef& e, int index) const {
  if (e.kind == EntityKind::Light) return scene_->lights[index].position;
  const bool robot = e.kind == EntityKind::FootBot;
  const Pose2 pose = robot ? physics_->RobotPose(index) : physics_->ObstaclePose(index);
  return Vec3(pose.x, pose.y, robot ? scene_->robots[index].z : scene_->obstacles[index].z);
}

double EntityStore::Yaw(const EntityRef& e, int index) const {
  if (e.kind == EntityKind::FootBot) return physics_->RobotPose(index).yaw;
  if (e.kind == EntityKind::Light) return 0;
  return physics_->ObstaclePose(index).yaw;
}

void EntityStore::SetPose(const EntityRef& e, int index, const Pose2& pose) {
  if (e.kind == EntityKind::FootBot) {
    physics_->SetRobotPose(index, pose);
  } else if (e.kind == EntityKind::Light) {
    scene_->lights[index].position.x() = pose.x, scene_->lights[index].position.y() = pose.y;
  } else {
    SetObstaclePose(index, pose);
  }
  MarkChanged(false);
}

bool EntityStore::Movable(const EntityRef& e, int index) const {
  return e.kind == EntityKind::FootBot || (IsObstacle(e) && scene_->obstacles[index].movable);
}

int EntityStore::LedCount(const EntityRef& e, int index) const {
  if (e.kind == EntityKind::FootBot) return footbot::kLedCount;
  if (IsObstacle(e)) return static_cast<int>(scene_->obstacles[index].leds.size());
  return 0;
}

Color EntityStore::Led(const EntityRef& e, int index, int k) const {
  if (e.kind == EntityKind::FootBot) return (*robots_)[index].leds[k];
  return scene_->obstacles[index].leds[k].color;
}

void EntityStore::SetLed(const EntityRef& e, int index, int k, const Color& color) {
  const int count = LedCount(e, index);
  for (int j = 0; j < count; ++j) {
    if (k >= 0 && j != k) continue;
    if (e.kind == EntityKind::FootBot)
      (*robots_)[index].leds[j] = color;
    else
      scene_->obstacles[index].leds[j].color = color;
  }
  MarkChanged(false);  // cameras see it from the next sense
}

void EntityStore::SetLightIntensity(int index, double intensity) {
  scene_->lights[index].intensity = intensity;
  MarkChanged(false);
}

void EntityStore::SetLightColor(int index, const Color& color) {
  scene_->lights[index].color = color;
  MarkChanged(false);
}

void EntityStore::SetMedium(const EntityRef& e, int index, const std::string& medium) {
  if (e.kind == EntityKind::Light)
    scene_->lights[index].medium = medium;
  else if (IsObstacle(e))
    scene_->obstacles[index].led_medium = medium;
  MarkChanged(true);  // the media index who is in which medium
}

double EntityStore::BatteryLevel(int i) const {
  return (*robots_)[i].battery.charge / scene_->robots[i].battery.full_charge;
}

void EntityStore::SetBatteryLevel(int i, double level) {
  (*robots_)[i].battery.charge = level * scene_->robots[i].battery.full_charge;
}

void EntityStore::KillRobot(int i) {
  RobotState& r = (*robots_)[i];
  r.alive = false;
  r.wheel_left = r.wheel_right = 0;
  physics_->FreezeRobot(i);
}

std::string EntityStore::ObstacleProblemNow(const ObstacleDef& def) const {
  std::string problem = ObstacleProblem(def, scene_->experiment.limits);
  if (!problem.empty()) return problem;
  const Footprint f = ObstacleFootprint(def);
  for (size_t i = 0; i < scene_->robots.size(); ++i) {
    const Pose2 pose = physics_->RobotPose(static_cast<int>(i));
    Footprint robot;
    robot.center = {pose.x, pose.y};
    robot.radius = footbot::kRadius;
    if (FootprintsOverlap(f, robot)) return "it would overlap foot-bot '" + scene_->robots[i].id + "'";
  }
  return "";
}

std::string EntityStore::RoomProblem(bool robot) const {
  EntityCounts counts{static_cast<double>(scene_->robots.size()), static_cast<double>(Count() - scene_->robots.size())};
  (robot ? counts.robots : counts.objects) += 1;
  return EntityCountProblem(counts, scene_->experiment.limits);
}

}  // namespace essaim
