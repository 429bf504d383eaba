// Media state rebuilt after physics each tick: who hears whom (range and bearing), where
// lit LEDs are (cameras). Read-only during sensing.
#pragma once
#include <cmath>
#include <vector>

#include "devices/robot_state.h"
#include "model/model.h"
#include "physics/physics_world.h"

namespace essaim {

/// Points bucketed into square cells by counting sort: rebuilt every tick without
/// allocation (buffers sized by Setup). Cell coordinates are clamped, so points outside
/// the arena land in the border cells.
struct PointGrid {
  Vec2 origin = Vec2::Zero();
  double cell = 1;                 // m
  int nx = 1, ny = 1;
  std::vector<int> cell_start;     // nx*ny + 1 offsets into items
  std::vector<int> items;          // point numbers grouped by cell, ascending within a cell
  std::vector<int> cell_of;        // scratch: cell of each point
  /// Cells of about `cell` m over [min, max], at most ~`max_cells` of them, room for
  /// `max_items` entries.
  void Setup(const Vec2& min, const Vec2& max, double cell, size_t max_items, size_t max_cells);
  /// Buckets points 0..n-1 given by pos(i).
  template <class PosFn>
  void Build(int n, PosFn pos);
  /// Buckets discs 0..n-1 (centre pos(i), radius radius(i)) into every cell their box
  /// overlaps; at most `max_items` entries (see DiscEntries).
  template <class PosFn, class RadiusFn>
  void BuildDiscs(int n, PosFn pos, RadiusFn radius);
  /// Buckets boxes 0..n-1 ([lo(i), hi(i)]) into every cell they overlap; items grow past
  /// `max_items` only for absurd coordinates.
  template <class LoFn, class HiFn>
  void BuildBoxes(int n, LoFn lo, HiFn hi);
  /// Upper bound of the cells a disc of `radius` overlaps.
  size_t DiscEntries(double radius) const;
  int CellX(double x) const { return Cell((x - origin.x()) / cell, nx); }
  int CellY(double y) const { return Cell((y - origin.y()) / cell, ny); }
  /// floor(q) clamped to [0, n): safe for any double (NaN and ±inf land in an edge cell,
  /// never cast out of range). Inline and without floor(): the media stage asks for a few
  /// cells per device and per pair.
  static int Cell(double q, int n) {
    if (!(q < n)) return n - 1;
    return q >= 0 ? static_cast<int>(q) : 0;  // truncation is floor for q >= 0
  }
};

/// A lit LED of the current tick (robot ring/beacon, box or cylinder LED, <light>).
struct LitLed {
  Vec3 pos = Vec3::Zero();         // m, world
  Color color;
  int robot = -1;                  // carrier robot, else -1
  int obstacle = -1;               // carrier box/cylinder, else -1
  int medium = 0;                  // index into Model::led_media
};

struct Media {
  bool ready = false;
  /// rab_inbox[r] = senders whose packet robot r receives this tick, ascending index.
  std::vector<std::vector<int>> rab_inbox;
  // ---- occluders this tick, for RAB and cameras: exact circle/box tests that decide what
  // one Box2D ray would (PhysicsWorld::CastRay), without walking Box2D's tree per ray.
  std::vector<Vec2> body_xy;       // every robot body (dead ones too)
  std::vector<Vec2> obstacle_xy;   // every box/cylinder centre
  std::vector<Vec2> obstacle_cs;   // cos, sin of its yaw
  std::vector<double> obstacle_radius;  // bounding circle (m)
  /// Bounding box of each footprint this tick, widened far beyond rounding: a segment whose
  /// box misses it cannot enter the obstacle (skips the exact test, same answer).
  std::vector<Vec2> obstacle_lo, obstacle_hi;
  std::vector<double> obstacle_top;     // m
  double obstacle_max_radius = 0;
  // ---- range and bearing (spec §5)
  std::vector<int> rab_medium;     // per robot: index into Model::rab_media; -1 no sensor
  std::vector<char> rab_member;    // this tick: in a medium and alive
  std::vector<Vec3> rab_pos;       // device position this tick (m)
  std::vector<double> rab_yaw;     // heading this tick (rad)
  int rab_devices = 0;             // robots with a RAB sensor in a medium
  double rab_max_range = 0;        // m, largest rab_range of a member
  PointGrid rab_grid;              // bodies, cell = reach + body radius
  /// Obstacles by bounding box, in every cell it overlaps; cells of about a quarter of the
  /// reach, so that a pair's segment visits few cells and each lists few obstacles.
  PointGrid rab_obstacle_grid;
  /// A body that may hide a partner from one device: the parts of CircleEntry that do not
  /// depend on the partner (offset s from the device, |s|² - r²), computed once per device.
  struct NearBody {
    double cc, sx, sy;
    int body;
    int bucket;  // of cc, see RabPartners
  };
  /// One thread's working buffers for the devices it routes (sized once, reused).
  struct RabScratch {
    std::vector<int> near;             // members after the device within reach, any order
    std::vector<NearBody> occluders;   // those that may hide a partner, bucketed by cc
    std::vector<NearBody> unsorted;    // occluders before bucketing
    std::vector<int> bucket_end;       // kOccluderBuckets + 1 offsets into occluders
    std::vector<int> sector_blocker;   // kProbeSectors occluders or -1, see FindBlockers
    std::vector<int> near_obstacles;   // within reach of one device, if few (kFewObstacles)
    std::vector<int> obstacle_stamp;   // dedup of near_obstacles
    int stamp = 0;
  };
  /// Up to this many obstacles within reach, a device's pairs test them all; beyond, each
  /// pair walks the obstacle grid's cells along its segment.
  static constexpr int kFewObstacles = 12;
  static constexpr int kOccluderBuckets = 64;
  /// Blocker probes (rab_blockers.h): direction sectors (a power of 2), the reach of the
  /// bodies that may block one, and how many within it make a crowd (fewer: no probes, as
  /// most pairs are then unhidden and probing would not pay).
  static constexpr int kProbeSectors = 64;
  static constexpr double kBlockerReach = 1.0;  // m
  static constexpr int kCrowd = 16;
  std::vector<RabScratch> rab_scratch;  // one per slot of the runner (UpdateMedia)
  /// rab_partners[a] = the partners b > a that a reaches unhidden, ascending, each as
  /// b << 2 | (a hears b) | (b hears a) << 1; merged into rab_inbox in ascending a.
  std::vector<std::vector<int>> rab_partners;
  // ---- LEDs and cameras (spec §7.1, §7.2)
  std::vector<int> led_medium;     // per robot: its leds actuator's medium, -1 none
  std::vector<int> camera_medium;  // per robot: its camera's medium, -1 none
  std::vector<int> obstacle_led_medium;  // per obstacle, -1 none
  std::vector<int> light_medium;   // per <light>
  bool any_camera = false;
  double camera_half_range = 0;    // m, largest z_cam·tan(aperture) of a camera robot
  std::vector<LitLed> leds;        // lit LEDs this tick; their order is the blobs' order
  PointGrid led_grid;
  PointGrid camera_body_grid;      // bodies, cells of about a camera's half range
  PointGrid camera_obstacle_grid;  // obstacles, in every cell they overlap
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
void UpdateMedia(const Model& model, const PhysicsWorld& physics, const std::vector<RobotState>& robots, Media* media,
                 const SlotRunner& runner = SlotRunner());

/// Segment fraction at which from -> to enters a circle (Box2D's circle ray cast); 2 when
/// it misses, also when it starts inside. Inline: the media stage calls it for every
/// (pair, body) in range, ~11% of a 300-robot foraging run as a call (issue 12).
inline double CircleEntry(const Vec2& a, const Vec2& b, const Vec2& c, double r) {
  // b2CircleShape::RayCast: the smaller root of |a + t(b - a) - c| = r, if in [0, 1].
  const Vec2 s = c - a;
  const double cc = s.squaredNorm() - r * r;
  if (cc < 0) return 2;
  const Vec2 d = b - a;
  const double dd = d.squaredNorm();
  const double bq = s.dot(d);
  const double disc = bq * bq - dd * cc;
  if (disc < 0 || dd <= 0) return 2;
  const double t = (bq - std::sqrt(disc)) / dd;
  return t >= 0 && t <= 1 ? t : 2;
}
/// Same for a box of half sizes (hx, hy), yaw (cos, sin) = cs (Box2D's polygon ray cast).
double BoxEntry(const Vec2& from, const Vec2& to, const Vec2& center, const Vec2& cs, double hx, double hy);
/// Whether a ray from -> to at height z meets a robot body (not `exclude_robot`) or an
/// obstacle spanning z (not `skip_obstacle`): CastRay's rule, via the camera grids.
bool CameraRayBlocked(const Model& model, const Media& media, const Vec2& from, const Vec2& to, double z,
                      int exclude_robot, int skip_obstacle);

/// World position of foot-bot LED `i` (0..12: ring 0..11 then beacon) for a robot at
/// `pose`, base height `z`, turret rotation `turret` (rad; the ring rides on the turret).
Vec3 FootBotLedPosition(const Pose2& pose, double z, double turret, int i);

}  // namespace essaim
