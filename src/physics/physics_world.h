// The only Box2D user (Box2D 2.4.1 from Debian). Robots, boxes and cylinders as bodies;
// wheel commands as a velocity servo with capped force and torque (as ARGoS's dynamics2d); ray and
// overlap queries through Box2D's dynamic tree. No Box2D type crosses this header.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "core/math.h"
#include "model/model.h"

namespace essaim {

/// What a ray or query touched.
/// Gripper: a foot-bot's gripper disc (index: its robot), which rays meet but nothing
/// collides with (ARGoS's dynamics2d makes it a sensor shape).
enum class BodyKind : int { None = 0, Robot = 1, Obstacle = 2, Gripper = 3 };

/// What a robot's gripper holds (kind None: nothing).
struct GripTarget {
  BodyKind kind = BodyKind::None;
  int index = -1;  // robot or obstacle index
  bool Holding() const { return kind != BodyKind::None; }
};

/// Radius of the foot-bot gripper's disc, centred at the body radius in front of the
/// turret, as tall as the body (ARGoS's dynamics2d gripper shape). Other robots' rays meet
/// it (proximity, scanner, light, camera and range-and-bearing lines); it collides with
/// nothing and has no mass of its own.
constexpr double kGripperRadius = 0.01;  // m

struct RayHit {
  BodyKind kind = BodyKind::None;
  int index = -1;       // robot or obstacle index
  double distance = 0;  // m from the ray start
  Vec2 point = Vec2::Zero();
  bool Hit() const { return kind != BodyKind::None; }
};

/// One shape a bundle of rays may hit (PhysicsWorld::GatherRayCandidates): the Box2D
/// fixture (opaque here) and a circle that bounds it, for a cheap per-ray reject.
struct RayCandidate {
  double near = 0;                // m, no point of the shape is closer to the gather centre
  double cx = 0, cy = 0, r = 0;   // m, bounding circle (inflated by 1 mm)
  const void* fixture = nullptr;  // b2Fixture*
};

/// The shapes near one robot, gathered once per tick for all its rays at one height,
/// nearest first (`near` never decreases along `items`), so a ray stops looking once no
/// shape left can beat its closest hit. Reused: after the densest neighbourhood it never
/// allocates.
struct RayCandidates {
  std::vector<RayCandidate> items;
  Vec2 center = Vec2::Zero();         // m, the gather centre
  std::vector<RayCandidate> scratch;  // the gather's unsorted list
  std::vector<int> bucket_ends;       // the gather's counting sort
};

/// Runs job(ctx, item) for items 0..n-1, maybe concurrently: how the sim layer lends its
/// thread pool to the physics (which knows no threads). No `run`: one after another.
struct PhysicsRunner {
  using Job = void (*)(void* ctx, int item);
  void* pool = nullptr;
  void (*run)(void* pool, int n, Job job, void* ctx) = nullptr;
};

/// The bodies of an experiment, in one Box2D world, or in one world per region when the
/// model declares several (each body lives in the region that holds its centre; between
/// ticks bodies migrate, and each world holds static or kinematic "ghost" copies of the
/// other regions' bodies near its own, so that contacts across a boundary happen:
/// docs/physics-regions.md says what that guarantees).
class PhysicsWorld {
 public:
  struct Impl;  // defined in physics_world_impl.h, for physics/ only

  explicit PhysicsWorld(const Model& model);
  ~PhysicsWorld();
  PhysicsWorld(const PhysicsWorld&) = delete;
  PhysicsWorld& operator=(const PhysicsWorld&) = delete;

  /// Wheel speeds in m/s. The heading used is the body's at this call (ARGoS freezes it
  /// per tick). Both zero: the robot brakes, resisting pushes up to its force caps.
  /// Writes only this robot's servo body: calls for distinct robots may run concurrently.
  void SetWheelSpeeds(int robot, double left, double right);
  /// One tick: `substeps` Box2D steps of dt/substeps. Several regions: first the bodies
  /// migrate and the ghosts follow their owners (one thread, in index order), then the
  /// regions step at once on `runner`. Results do not depend on the runner.
  void Step(double dt, int substeps, const PhysicsRunner& runner = PhysicsRunner());
  /// Whether a robot that touches nothing is moved outside Box2D while that gives Box2D's
  /// result bit for bit (physics_dormant_robots.cpp; on by default). Off, Box2D steps every
  /// robot: for tests and measurements, the results are the same.
  void SetDormancy(bool on);
  /// Robot sub-steps done outside Box2D so far.
  int64_t DormantSubsteps() const;
  /// Box2D worlds: the model's regions, at least one.
  int RegionCount() const;
  /// The region whose world holds the robot's body now.
  int RobotRegion(int robot) const;

  int RobotCount() const { return static_cast<int>(robots_.size()); }
  int ObstacleCount() const { return static_cast<int>(obstacles_.size()); }
  /// Yaw is Box2D's accumulated, unwrapped body angle (ARGoS's quaternion uses it).
  Pose2 RobotPose(int robot) const;
  Vec2 RobotVelocity(int robot) const;
  double RobotAngularVelocity(int robot) const;
  void SetRobotPose(int robot, const Pose2& pose);
  Pose2 ObstaclePose(int obstacle) const;
  /// A box or cylinder as the model describes it; returns its index (the next one).
  int AddObstacle(const ObstacleDef& obstacle);
  /// Destroys obstacle `index` (grips on it released); later obstacles move down one index.
  void RemoveObstacle(int index);
  /// A foot-bot added during a run (loop functions), as the model describes it; returns
  /// its index (the next one). No overlap check: ARGoS adds where it is told.
  int AddRobot(const RobotDef& robot);
  /// Undoes the last AddRobot (its controller could not be made).
  void RemoveLastRobot();
  /// Teleports an obstacle (velocity zeroed), static ones included.
  void SetObstaclePose(int index, const Pose2& pose);
  /// The body of a dead robot stays (an obstacle others bump into) but is braked.
  void FreezeRobot(int robot);

  /// Closest hit along from→to among shapes whose height reaches `z` (m above the floor),
  /// ignoring robot `exclude_robot` (-1: none). Thread-safe (read-only).
  RayHit CastRay(const Vec2& from, const Vec2& to, double z, int exclude_robot) const;
  /// Rays cast from within `radius` of `center`, at height `z`, ignoring robot
  /// `exclude_robot`: gathers once (one tree query) every shape such a ray can hit.
  void GatherRayCandidates(const Vec2& center, double radius, double z, int exclude_robot, RayCandidates* out) const;
  /// GatherRayCandidates for rays on half-lines from `center`, within `radius` of it, whose
  /// directions lie between unit vectors `u0` and `u1` (counter-clockwise from u0, less than π
  /// on): only the shapes that come near that sector, from the grid cells over it. A scanner's
  /// long sensor sweeps six rays through a narrow sector of its 1.5 m disc.
  void GatherWedgeCandidates(const Vec2& center, double radius, const Vec2& u0, const Vec2& u1, double z,
                             int exclude_robot, RayCandidates* out) const;
  /// CastRay's distance for a ray inside the gathered disc, tested against the candidates
  /// only, with Box2D's own shape ray casts: the same closest fraction, bit for bit (the
  /// closest of several hits does not depend on the order they are tested in, and the
  /// shapes skipped once the nearest-first scan passes the closest hit cannot beat it).
  /// Kind and index are those of the first closest in that order (ties are rare).
  RayHit CastRay(const RayCandidates& candidates, const Vec2& from, const Vec2& to) const;
  /// Robots whose centres lie within `radius` of `center`, by index (via the tree, not all pairs).
  void RobotsNear(const Vec2& center, double radius, std::vector<int>* out) const;

  // ---- gripper (physics_grip.cpp): the turret angle `turret` (rad, relative to the body) is
  // robot state kept by devices/turret.cpp; physics holds the disc and the spring.
  /// Centre of the gripper disc: body radius in direction yaw + turret.
  Vec2 GripperPoint(int robot, double turret) const;
  /// Centre of the robot's gripper disc as the rays see it now (the turret last applied).
  Vec2 GripperDiscPoint(int robot) const;
  /// The gripper's lock, for the steps that follow. A locked gripper that holds nothing
  /// grips, before any sub-step, the grippable shape (movable box or cylinder, another robot)
  /// overlapping its disc — the deepest if several — with ARGoS's damped spring: from the
  /// robot's centre to the contact point, rest length their distance then, stiffness
  /// `gripping_rigidity`, acting from the next sub-step. An unlocked gripper that holds
  /// something lets go after the first sub-step in which its disc touches a grippable shape
  /// (what it holds or another), as ARGoS does. Holding allocates nothing.
  void SetGripperLocked(int robot, bool locked);
  /// Lets go of what the robot holds now (no-op if nothing); the lock stays.
  void Release(int robot);
  /// Turns the gripper disc with the turret (the spring's end at the robot's centre stays).
  void SetGripTurret(int robot, double turret);
  GripTarget Gripped(int robot) const;

 private:
  /// Brings the grid that GatherRayCandidates reads up to date (thread-safe).
  void EnsureRayGrid() const;
  /// Moves `out->scratch` (its `near` within [lo, hi]) into `out->items`, nearest first.
  static void SortNearestFirst(double lo, double hi, RayCandidates* out);

  /// Several regions, before a step: each body (with what it grips or is gripped by) moves
  /// to the region holding its centre, then ghosts are made, moved or dropped.
  void SyncRegions(double dt, const PhysicsRunner& runner);
  /// Several regions, one tick: the sync, then each sub-step on every region at once.
  void StepRegions(double dt, int substeps, const PhysicsRunner& runner);
  /// Every moving dynamic body moved `h` seconds along its velocity (see Step).
  void ShiftDynamicBodies(float h);
  /// Several regions, between two sub-steps: each ghost takes its body's pose and velocity.
  void FollowGhosts(const PhysicsRunner& runner);
  /// One region's sub-steps first .. first + count - 1 of a tick, with the grips' springs.
  void StepRegion(int region, int first, int count, float h);
  /// StepRegion as a PhysicsRunner job (ctx: the sub-steps).
  static void StepRegionJob(void* ctx, int region);
  /// Before a tick's sub-steps: the robots that hold or are locked, and their grips and
  /// releases at the tick's start (every region's shapes; a grip brings its target over).
  void BeginGripTick(int substeps);
  /// After a tick's sub-steps: this tick's grips act from the first sub-step of the next.
  void EndGripTick();
  /// Grips and releases decided before sub-step `substep` (region -1: every region's).
  void GripEvents(int region, int substep);
  /// The springs of the region's holders, for one sub-step of `h` seconds.
  void ApplyGripSprings(int region, int substep, float h);
  /// Releases that took effect in sub-step `substep`.
  void EndGripSubstep(int region, int substep);
  /// The b2Body* robot `robot` holds, or null.
  void* HeldBody(int robot) const;
  /// Moves what grip target `t` belongs to (it and every body tied to it by grips) into
  /// region `region`; returns the target's body there.
  void* MoveGripGroupVoid(const GripTarget& t, int region);
  /// Robot `index`'s body and its servo, in the region holding its pose.
  void AddRobotBody(const RobotDef& robot, int index);
  std::unique_ptr<Impl> impl_;
  std::vector<void*> robots_;     // b2Body*
  std::vector<void*> obstacles_;  // b2Body*
};

}  // namespace essaim
