// Media state rebuilt after physics each tick: who hears whom (range and bearing, in
// rab_routing.cpp), where lit LEDs are (the LED field, led_field.cpp) and what hides them
// from cameras (camera_occlusion.cpp). Read-only during sensing.
#pragma once
#include <vector>

#include "devices/rab_routing.h"
#include "devices/robot_state.h"
#include "model/model.h"
#include "physics/physics_world.h"
#include "spatial/segment.h"
#include "spatial/uniform_grid.h"

namespace essaim {

/// A lit LED of the current tick (robot ring/beacon, box or cylinder LED, <light>).
struct LitLed {
  Vec3 pos = Vec3::Zero();  // m, world
  Color color;
  int robot = -1;     // carrier robot, else -1
  int obstacle = -1;  // carrier box/cylinder, else -1
  int medium = 0;     // index into Model::led_media
};

struct Media {
  bool ready = false;
  /// rab_inbox[r] = senders whose packet robot r receives this tick, ascending index.
  std::vector<std::vector<int>> rab_inbox;
  // ---- occluders this tick, for RAB and cameras: exact circle/box tests that decide what
  // one Box2D ray would (PhysicsWorld::CastRay), without walking Box2D's tree per ray.
  std::vector<Vec2> body_xy;            // every robot body (dead ones too)
  std::vector<Vec2> gripper_xy;         // its gripper disc's centre (radius kGripperRadius)
  std::vector<Vec2> obstacle_xy;        // every box/cylinder centre
  std::vector<Vec2> obstacle_cs;        // cos, sin of its yaw
  std::vector<double> obstacle_radius;  // bounding circle (m)
  /// Bounding box of each footprint this tick, widened far beyond rounding: a segment whose
  /// box misses it cannot enter the obstacle (skips the exact test, same answer).
  std::vector<Vec2> obstacle_lo, obstacle_hi;
  std::vector<double> obstacle_top;  // m
  // ---- range and bearing
  std::vector<int> rab_medium;   // per robot: index into Model::rab_media; -1 no sensor
  std::vector<char> rab_member;  // this tick: in a medium and alive
  std::vector<Vec3> rab_pos;     // device position this tick (m)
  std::vector<double> rab_yaw;   // heading this tick (rad)
  int rab_devices = 0;           // robots with a RAB sensor in a medium
  double rab_max_range = 0;      // m, largest rab_range of a member
  /// m², this tick: a circle of this radius around a body holds the body and its gripper
  /// disc with a margin far above rounding (RabOccluder::bound2).
  double rab_bound_radius2 = 0;
  UniformGrid rab_grid;  // bodies, cell = reach + body radius
  /// Obstacles by bounding box, in every cell it overlaps; cells of about a quarter of the
  /// reach, so that a pair's segment visits few cells and each lists few obstacles.
  UniformGrid rab_obstacle_grid;
  std::vector<RabScratch> rab_scratch;  // one per slot of the runner (UpdateMedia)
  /// rab_partners[a] = the partners b > a that a reaches unhidden, ascending, each as
  /// b << 2 | (a hears b) | (b hears a) << 1; merged into rab_inbox in ascending a.
  std::vector<std::vector<int>> rab_partners;
  // ---- LEDs and cameras
  std::vector<int> led_medium;           // per robot: its leds actuator's medium, -1 none
  std::vector<int> camera_medium;        // per robot: its camera's medium, -1 none
  std::vector<int> obstacle_led_medium;  // per obstacle, -1 none
  std::vector<int> light_medium;         // per <light>
  bool any_camera = false;
  double camera_half_range = 0;  // m, largest z_cam·tan(aperture) of a camera robot
  std::vector<LitLed> leds;      // lit LEDs this tick; their order is the blobs' order
  UniformGrid led_grid;
  UniformGrid camera_body_grid;      // bodies, cells of about a camera's half range
  UniformGrid camera_obstacle_grid;  // obstacles, in every cell they overlap
};

/// Sizes every media buffer for the model (World creation). UpdateMedia calls it if needed.
void InitMedia(const Model& model, Media* media);
/// Runs job(ctx, slot) once for each slot 0..slots-1, maybe concurrently: how the sim
/// layer lends its thread pool to the media stage (devices know no threads). The default
/// runs the one slot on the calling thread.
struct SlotRunner {
  using Job = void (*)(void* ctx, int slot);
  int slots = 1;
  void* pool = nullptr;
  void (*run)(void* pool, Job job, void* ctx) = nullptr;
};
/// Media stage: rebuilds routing from the robots' positions after physics. The per-device
/// RAB work is spread over the runner's slots; inboxes do not depend on their number.
void UpdateMedia(const Model& model, const PhysicsWorld& physics, const RobotStates& robots, Media* media,
                 const SlotRunner& runner = SlotRunner());

/// Whether a shape hides the 3D segment from -> to, by ARGoS's ray rule (its entry point's
/// height, or its crossing of the shape's top): a robot body or gripper disc (not robot
/// `exclude_robot`'s), a box or a cylinder (not `skip_obstacle`). Via the camera grids.
bool CameraRayBlocked(const Model& model, const Media& media, const Vec3& from, const Vec3& to, int exclude_robot,
                      int skip_obstacle);

/// World position of foot-bot LED `i` (0..12: ring 0..11 then beacon) for a robot at
/// `pose`, base height `z`, turret rotation `turret` (rad; the ring rides on the turret).
Vec3 FootBotLedPosition(const Pose2& pose, double z, double turret, int i);

// ---- shared by the media's rooms (media.cpp, rab_routing.cpp, led_field.cpp, camera_occlusion.cpp)

/// Index of the medium called `id` among `media`, -1 if none.
template <class Def>
int MediumIndex(const std::vector<Def>& media, const std::string& id) {
  for (size_t k = 0; k < media.size(); ++k)
    if (media[k].id == id) return static_cast<int>(k);
  return -1;
}
/// Where segment a -> b enters obstacle k at its pose this tick (CircleEntry or BoxEntry).
double ObstacleEntry(const ObstacleDef& o, const Media& m, int k, const Vec2& a, const Vec2& b);
/// The part of segment a -> b over obstacle k's footprint (CircleSpan or BoxSpan).
bool ObstacleSpan(const ObstacleDef& o, const Media& m, int k, const Vec2& a, const Vec2& b, double* t0, double* t1);
/// A grid over [lo, hi] of the obstacles, each in every cell its bounding disc, widened by
/// `slack_cells` cells, overlaps (a box's margins need half a cell).
void CoverObstacles(const Vec2& lo, const Vec2& hi, double cell, double slack_cells, const Media& m, UniformGrid* g);
/// Sizes the LED field (InitMedia); UpdateLedField lists this tick's lit LEDs.
void InitLedField(const Model& model, Media* m);
void UpdateLedField(const Model& model, const PhysicsWorld& physics, const RobotStates& robots, Media* m);
/// Sizes the cameras' occlusion grids (InitMedia, after the LED field); FileCameraOccluders
/// files this tick's bodies and obstacles in them.
void InitCameraOcclusion(const Model& model, Media* m);
void FileCameraOccluders(Media* m);

}  // namespace essaim
