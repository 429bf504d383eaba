#include "devices/entity_store.h"

#include <algorithm>
#include <cstring>

namespace essaim {

namespace {
constexpr const char* kKindNames[] = {"foot-bot", "box", "cylinder", "light"};

EntityKind ObstacleKind(const ObstacleDef& o) { return o.kind == ShapeKind::Box ? EntityKind::Box : EntityKind::Cylinder; }
}  // namespace

const char* EntityKindName(EntityKind kind) { return kKindNames[static_cast<int>(kind)]; }

bool ParseEntityKind(const char* name, EntityKind* kind) {
  for (int k = 0; k < 4; ++k)
    if (!std::strcmp(name, kKindNames[k])) return *kind = static_cast<EntityKind>(k), true;
  return false;
}

void EntityStore::Init(Model* scene, PhysicsWorld* physics) {
  scene_ = scene;
  physics_ = physics;
  order_.clear();
  added_.clear();
  obstacle_serial_.clear(), light_serial_.clear(), obstacle_index_.clear(), light_index_.clear();
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
    case EntityKind::FootBot: return e.serial < scene_->robots.size() ? static_cast<int>(e.serial) : -1;
    case EntityKind::Light: return e.serial < light_index_.size() ? light_index_[e.serial] : -1;
    default: return e.serial < obstacle_index_.size() ? obstacle_index_[e.serial] : -1;
  }
}

bool EntityStore::HasId(const std::string& id) const {
  for (const RobotDef& r : scene_->robots)
    if (r.id == id) return true;
  for (const ObstacleDef& o : scene_->obstacles)
    if (o.id == id) return true;
  for (const LightDef& l : scene_->lights)
    if (l.id == id) return true;
  return false;
}

EntityRef EntityStore::AddObstacle(const ObstacleDef& def) {
  const uint32_t serial = static_cast<uint32_t>(obstacle_index_.size());
  const int index = physics_->AddObstacle(def);
  scene_->obstacles.push_back(def);
  obstacle_serial_.push_back(serial);
  obstacle_index_.push_back(index);
  EntityRef e{ObstacleKind(def), serial};
  order_.push_back(e);
  added_.push_back(e);
  MarkChanged(true);
  return e;
}

EntityRef EntityStore::AddLight(const LightDef& def) {
  const uint32_t serial = static_cast<uint32_t>(light_index_.size());
  light_serial_.push_back(serial);
  light_index_.push_back(static_cast<int>(scene_->lights.size()));
  scene_->lights.push_back(def);
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

}  // namespace essaim
