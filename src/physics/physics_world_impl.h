// PhysicsWorld's insides, shared by its sources: physics_world.cpp (bodies and fixtures),
// physics_step.cpp (the step), physics_rays.cpp (rays and neighbour queries),
// physics_grip.cpp (the gripper) and physics_regions_sync.cpp (several regions: migration and
// ghosts). Not included anywhere else: Box2D types stay inside physics/.
#pragma once
#include <box2d/box2d.h>

#include <atomic>
#include <climits>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include "physics/physics_world.h"
#include "spatial/uniform_grid.h"

namespace essaim {

// Fixture user data: kind in the low 2 bits, index above. Heights live in a side table.
// A ghost's fixtures carry kind None: queries, rays and grips never see them.
inline uintptr_t PackTag(BodyKind kind, int index) {
  return (static_cast<uintptr_t>(index) << 2) | static_cast<uintptr_t>(kind);
}
inline BodyKind TagKind(uintptr_t tag) { return static_cast<BodyKind>(tag & 3); }
inline int TagIndex(uintptr_t tag) { return static_cast<int>(tag >> 2); }

inline b2Body* AsBody(void* p) { return static_cast<b2Body*>(p); }

/// A shape as the ray grid files it: a circle containing it, its vertical extent.
struct ShapeCircle {
  double cx = 0, cy = 0, r = 0;  // m
  double bottom = 0, top = 0;    // m
  int robot = -1;                // robot index, -1 for obstacles
  const b2Fixture* fixture = nullptr;
};

struct PhysicsWorld::Impl {
  /// One Box2D world per region of the arena (one for the whole arena unless the model
  /// declares several), each with its own ground for floor friction.
  struct Region {
    std::unique_ptr<b2World> world;
    b2Body* ground = nullptr;
  };
  std::vector<Region> regions;
  std::vector<PhysicsRegionDef> region_defs;  // empty with one region
  std::vector<b2Body*> controls;              // kinematic servo targets, one per robot
  std::vector<double> obstacle_top;           // m, top of each obstacle
  std::vector<double> obstacle_bottom;
  /// One gripper per robot (physics_grip.cpp). Holding: ARGoS's damped spring from the
  /// robot's centre to `anchor` on the held body, no Box2D joint (the two still collide).
  struct Grip {
    GripTarget target;    // what the spring holds (kind None: nothing)
    b2Vec2 anchor{0, 0};  // the spring's end, in the held body's frame (m)
    double rest = 0;      // rest length (m)
    bool locked = false;  // the gripper's lock, as the last Act set it
    int from = 0;         // this tick, the spring acts from this sub-step on
    int until = INT_MAX;  // ... and to this one, then it is gone (released)
    double turret = 0;    // the disc's turret angle after this tick (rad)
    double turn = 0;      // how far it turns over this tick (rad): ARGoS turns it sub-step by sub-step
  };
  std::vector<Grip> grips;
  std::vector<int> grip_robots;      // this tick: the robots that hold or are locked, by index
  double gripping_rigidity = 10000;  // N/m, the spring's stiffness
  int substeps = 1;                  // this tick's
  PhysicsDef phys;                   // friction of obstacles added later

  /// Several regions: each body's copies in the other regions' worlds, [index][region]
  /// (null where none). A ghost is a static (of a static body) or kinematic copy moving at
  /// the owner's velocity, so that bodies near a boundary meet their neighbours.
  std::vector<std::vector<b2Body*>> robot_ghosts, obstacle_ghosts;
  /// This tick's (body, ghost) pairs: the ghosts follow their bodies before each sub-step.
  // Each region's (body, its ghost there) pairs: a region's ghosts follow on its own task.
  std::vector<std::vector<std::pair<b2Body*, b2Body*>>> ghost_pairs;
  /// The region sync's scratch, sized once (union-find over grips, owner regions, boxes).
  std::vector<int> parent, owner, current;
  std::vector<b2AABB> region_boxes;
  std::vector<b2AABB> body_boxes;  // each node's, this tick

  /// Ray candidates come from a grid of these circles (EnsureRayGrid), rebuilt at the first
  /// query after shapes moved: every change to a body's place or to the set of shapes counts
  /// up `shapes_moved` (never during a parallel stage; queries only read it).
  std::vector<ShapeCircle> ray_circles;
  UniformGrid ray_grid;
  uint64_t shapes_moved = 0;
  std::atomic<uint64_t> grid_built_at{~uint64_t{0}};
  std::mutex grid_mutex;

  /// One robot's wheel servo as physics_free_robots.cpp solves it while the robot touches
  /// nothing: the friction joint's accumulated impulses, carried from sub-step to sub-step.
  /// The servo body's velocity, the joint's caps and the robot's inverse mass and moment are
  /// copied here (Box2D's own floats), so that a free robot's solve reads no other object.
  struct FreeServo {
    b2Vec2 linear{0, 0};                  // N·s
    float angular = 0;                    // N·m·s
    b2Vec2 v{0, 0};                       // m/s, the servo body's velocity
    float w = 0;                          // rad/s
    float max_force = 0, max_torque = 0;  // N, N·m
    float inv_mass = 0, inv_moment = 0;   // as b2Body's m_invMass, m_invI
    bool free = false;                    // solved outside Box2D now: its servo body is disabled
    int tied_at = -1;                     // the last sub-step stamp at which a grip tied the robot
    /// Dormant (physics_dormant_robots.cpp): asleep in Box2D, moved here; its pose and velocity.
    bool dormant = false;
    b2Vec2 c{0, 0};  // m, Box2D's sweep centre (the body's origin)
    float a = 0;     // rad
    b2Vec2 vel{0, 0};
    float spin = 0;  // rad/s
    b2AABB tree;     // its proxy's box in the broad-phase tree, which stays put while it sleeps
  };
  /// Each robot's gripper disc (kGripperRadius), a fixture on a static, disabled body of its
  /// own (physics_grip.cpp): out of Box2D's broadphase, on its robot's pose between steps.
  std::vector<b2Body*> discs;
  std::unique_ptr<b2World> disc_shelf;  // holds the discs' bodies; never stepped
  std::vector<FreeServo> free_servos;   // one per robot (used with one region only)
  float inv_dt0 = 0;                    // 1/h of the world's last step: Box2D's warm-start ratio
  int substep_stamp = 0;                // counts sub-steps, for FreeServo::tied_at
  bool dormancy = true;                 // PhysicsWorld::SetDormancy
  int64_t dormant_substeps = 0;         // robot sub-steps done outside Box2D so far

  int RegionCount() const { return static_cast<int>(regions.size()); }
  /// Index of the region whose world holds `body`.
  int RegionOfBody(const b2Body* body) const {
    for (size_t r = 0; r < regions.size(); ++r)
      if (regions[r].world.get() == body->GetWorld()) return static_cast<int>(r);
    return 0;
  }
};

/// Robot `index`'s gripper disc body (its fixture tagged Gripper `index`), turret at 0, made in
/// `shelf` (Impl::disc_shelf).
b2Body* MakeGripperDisc(b2World* shelf, const b2Body* robot, int index);
/// Puts robot `index`'s disc body (`robot`: its b2Body) on its robot's pose.
void SyncGripperDisc(PhysicsWorld::Impl* im, const b2Body* robot, int index);
/// Puts every robot's disc body on its robot's pose.
void SyncGripperDiscs(PhysicsWorld::Impl* im, const std::vector<void*>& robots);

/// One region's world, before a sub-step of `h` seconds (physics_free_robots.cpp): each robot
/// that Box2D would solve alone with its servo (no touching contact, no grip) has that servo
/// solved here, exactly as Box2D's friction joint would, and its servo body disabled, so that
/// Box2D's island holds the robot alone; the others get their servo back. `first`: the tick's
/// first sub-step, whose new contacts are found first.
void SolveFreeServos(PhysicsWorld::Impl* im, const std::vector<void*>& robots, bool first, float h);
/// The friction joint's solve between a free robot's kinematic servo and the robot's velocity
/// `v`, `w` (physics_free_robots.cpp): Box2D's float operations for a lone body.
void SolveServo(b2Vec2* v, float* w, float h, float dt_ratio, PhysicsWorld::Impl::FreeServo* s);
/// One sub-step of a free robot with no contact done outside Box2D, exactly as Box2D would
/// have done it, the body put to sleep for it (physics_dormant_robots.cpp); false where that
/// cannot be exact (its body then is awake, as before the call).
bool DormantSubstep(b2Body* body, PhysicsWorld::Impl::FreeServo* s, float h, float dt_ratio);
/// Wakes a dormant robot: its pose (moved `shift` seconds along its velocity, as the
/// sub-step shift moves a body) and velocity back into Box2D.
void WakeDormant(b2Body* body, PhysicsWorld::Impl::FreeServo* s, float shift);
/// After the world stepped `h` seconds: the ratio Box2D's next warm start uses.
inline void NoteStep(PhysicsWorld::Impl* im, float h) { im->inv_dt0 = 1.0f / h; }

}  // namespace essaim
