// The entities of a run as loop functions see them (ARGoS's CSpace): foot-bots, boxes,
// cylinders and lights in creation order, each with a serial that stays valid while
// indices shift. It edits the World's scene (a mutable copy of the Model that every
// sensor reads) and the physics together, and raises a "scene changed" flag that the
// step turns into a media refresh before anything senses again.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "model/model.h"
#include "physics/physics_world.h"

namespace essaim {

enum class EntityKind : uint8_t { FootBot, Box, Cylinder, Light };
/// "foot-bot", "box", "cylinder", "light".
const char* EntityKindName(EntityKind kind);
bool ParseEntityKind(const char* name, EntityKind* kind);

struct EntityRef {
  EntityKind kind = EntityKind::FootBot;
  uint32_t serial = 0;  // robots: their index; boxes/cylinders and lights: own counters
};

class EntityStore {
 public:
  /// Registers the scene's robots, obstacles and lights. `scene` and `physics` outlive it.
  void Init(Model* scene, PhysicsWorld* physics);

  /// Every live entity, creation order (the model's robots, obstacles, lights, then added ones).
  const std::vector<EntityRef>& All() const { return order_; }
  /// Every entity added after Init, in order, removed ones included (append-only: a
  /// recorder follows it by count).
  const std::vector<EntityRef>& Added() const { return added_; }
  /// Current index in scene->robots / obstacles / lights; -1 once removed.
  int IndexOf(const EntityRef& e) const;
  /// The ref of the obstacle at `index` now.
  EntityRef ObstacleRef(int index) const {
    return {scene_->obstacles[index].kind == ShapeKind::Box ? EntityKind::Box : EntityKind::Cylinder,
            obstacle_serial_[index]};
  }
  /// Whether `id` names a live entity.
  bool HasId(const std::string& id) const;

  /// Adds a box or cylinder (kind from `def.kind`) to the scene and the physics.
  EntityRef AddObstacle(const ObstacleDef& def);
  EntityRef AddLight(const LightDef& def);
  /// Removes a box, cylinder or light (robots cannot be removed). False if already gone.
  bool Remove(const EntityRef& e);
  void SetObstaclePose(int index, const Pose2& pose);

  Model& scene() { return *scene_; }
  /// Something sensors index changed (layout, poses, colours) since the last Take.
  void MarkChanged(bool layout) { changed_ = true, layout_changed_ |= layout; }
  bool changed() const { return changed_; }
  bool layout_changed() const { return layout_changed_; }
  void ClearChanged() { changed_ = layout_changed_ = false; }

 private:
  Model* scene_ = nullptr;
  PhysicsWorld* physics_ = nullptr;
  std::vector<EntityRef> order_;
  std::vector<EntityRef> added_;
  std::vector<uint32_t> obstacle_serial_, light_serial_;  // by current index
  std::vector<int> obstacle_index_, light_index_;         // by serial; -1 removed
  bool changed_ = false, layout_changed_ = false;
};

}  // namespace essaim
