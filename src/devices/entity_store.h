// The entities of a run as loop functions see them (ARGoS's CSpace): foot-bots, boxes,
// cylinders and lights in creation order, each with a serial that stays valid while
// indices shift. This is the one interface through which loop functions read and change
// the World: it edits the World's scene (a mutable copy of the Model that every sensor
// reads), the physics and the robots' states together, and raises a "scene changed" flag
// that the step turns into a media refresh before anything senses again. Loop functions
// call it only between stages.
#pragma once
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "devices/robot_state.h"
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

/// What the layers above the store do when a foot-bot joins during a run: make its
/// controller (a Lua state, its top-level chunk and init() run) for robot `index`, whose
/// def, state and body exist. False with `error` when the robot cannot run: the store then
/// takes it back out. The World installs one once its controllers are made.
class RobotJoiner {
 public:
  virtual ~RobotJoiner() = default;
  virtual bool Join(int index, std::string* error) = 0;
};

class EntityStore {
 public:
  /// Registers the scene's robots, obstacles and lights. `scene`, `physics` and `robots`
  /// (filled later, one per scene robot) outlive it.
  void Init(Model* scene, PhysicsWorld* physics, RobotStates* robots);
  /// Who makes the controllers of foot-bots added later (null: none can be added yet).
  void SetRobotJoiner(RobotJoiner* joiner) { joiner_ = joiner; }

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
  /// The id of live entity `e`.
  const std::string& IdOf(const EntityRef& e) const;
  /// Live entities of every kind.
  size_t Count() const;
  /// Changes whenever an entity is added or removed (not when one moves or changes colour).
  uint64_t LayoutVersion() const { return (static_cast<uint64_t>(added_.size()) << 32) | order_.size(); }

  // ---- reading and moving an entity `e` that is live at `index` (IndexOf)
  /// x, y from the physics (lights: the scene), z from the scene.
  Vec3 Position(const EntityRef& e, int index) const;
  /// Heading as the physics has it (unbounded); 0 for lights.
  double Yaw(const EntityRef& e, int index) const;
  /// A robot or obstacle through the physics, a light's x, y in the scene.
  void SetPose(const EntityRef& e, int index, const Pose2& pose);
  /// Robots and movable obstacles.
  bool Movable(const EntityRef& e, int index) const;
  const ObstacleDef& Obstacle(int index) const { return scene_->obstacles[index]; }
  const LightDef& Light(int index) const { return scene_->lights[index]; }

  // ---- LEDs (robots' own and obstacles') and lights
  int LedCount(const EntityRef& e, int index) const;
  Color Led(const EntityRef& e, int index, int k) const;
  /// LED `k`, or every LED when k < 0.
  void SetLed(const EntityRef& e, int index, int k, const Color& color);
  void SetLightIntensity(int index, double intensity);
  void SetLightColor(int index, const Color& color);
  /// The <led> medium a box's or cylinder's LEDs, or a light, are seen through ("": none).
  void SetMedium(const EntityRef& e, int index, const std::string& medium);

  // ---- robots, by index
  const RobotState& Robot(int i) const { return (*robots_)[i]; }
  Pose2 RobotPose(int i) const { return physics_->RobotPose(i); }
  /// Charge as a fraction of the robot's full charge.
  double BatteryLevel(int i) const;
  void SetBatteryLevel(int i, double level);
  /// Stops a robot for good: dead, wheels at rest, its body frozen.
  void KillRobot(int i);

  // ---- adding and removing, checked as the loader checks the .argos file
  /// Why `def` cannot be added now (over the limits, or overlapping a foot-bot where it
  /// stands), or "".
  std::string ObstacleProblemNow(const ObstacleDef& def) const;
  /// Why one entity more (a foot-bot when `robot`) is over the experiment's limit, or "".
  std::string RoomProblem(bool robot) const;

  /// Why foot-bot `def` cannot be added now (no controller can be made yet, an id taken,
  /// its controller or place outside the arena, over the limits), or "". Overlaps are
  /// allowed, as in ARGoS, whose loop functions add a robot and then move it somewhere free.
  std::string RobotProblemNow(const RobotDef& def) const;
  /// Adds a foot-bot (pose, devices from `def`; the controller named by `def.controller_id`,
  /// whose index and <params> it takes) to the scene, the
  /// physics and the robots' states, then has the joiner make its controller. False with
  /// `error` (and nothing added) when RobotProblemNow or the joiner says no.
  bool AddRobot(const RobotDef& def, EntityRef* added, std::string* error);
  /// Adds a box or cylinder (kind from `def.kind`) to the scene and the physics.
  EntityRef AddObstacle(const ObstacleDef& def);
  EntityRef AddLight(const LightDef& def);
  /// Removes a box, cylinder or light (robots cannot be removed: indices into every
  /// per-robot array stay put). False if already gone.
  bool Remove(const EntityRef& e);
  void SetObstaclePose(int index, const Pose2& pose);

  /// Something sensors index changed (layout, poses, colours) since the last ClearChanged.
  bool changed() const { return changed_; }
  bool layout_changed() const { return layout_changed_; }
  void ClearChanged() { changed_ = layout_changed_ = false; }

 private:
  /// Index of the <lua_controller> with this id in the scene, or -1.
  int ControllerIndex(const std::string& id) const;
  void MarkChanged(bool layout) { changed_ = true, layout_changed_ |= layout; }
  void AddId(const std::string& id) { ++ids_[id]; }
  void RemoveId(const std::string& id);
  Model* scene_ = nullptr;
  PhysicsWorld* physics_ = nullptr;
  RobotStates* robots_ = nullptr;
  RobotJoiner* joiner_ = nullptr;
  std::vector<EntityRef> order_;
  std::vector<EntityRef> added_;
  std::vector<uint32_t> obstacle_serial_, light_serial_;  // by current index
  std::vector<int> obstacle_index_, light_index_;         // by serial; -1 removed
  bool changed_ = false, layout_changed_ = false;
  // Live entities per id (HasId: a lookup, not a scan of the scene). Only looked up, never
  // iterated: its order cannot reach a result.
  std::unordered_map<std::string, int> ids_;
};

}  // namespace essaim
