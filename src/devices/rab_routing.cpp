// Range and bearing: who hears whom. Candidates come from a uniform grid of all robot
// bodies with cells of the largest rab_range (a device looks at the 3x3 cells around it:
// never all pairs). Occlusion uses exact circle and box tests against the bodies, their
// gripper discs and the obstacles near the device: what one ray per pair would find, as
// ARGoS (the first shape met, the sender's own aside, must be the partner's), without
// walking Box2D's tree for every pair. Devices are routed in parallel (each lists its
// partners b > a with its thread's scratch), then one serial pass fills the inboxes in
// ascending a: the same inboxes, in the same order, at any thread count.
#include "devices/rab_routing.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "devices/media.h"
#include "devices/rab_blockers.h"
#include "spatial/bucket_sort.h"
#include "spatial/segment.h"

namespace essaim {

namespace {
constexpr double kBodyRadius2 = footbot::kRadius * footbot::kRadius;  // m²

/// What one device's pairs share: its place, what occludes, how occluders are bucketed.
struct Device {
  int index;
  Vec3 pos;             // m, the device
  Vec2 xy;              // m, its planar position
  bool occlusions;      // its medium checks them
  bool bodies_occlude;  // robot bodies reach its height (as CastRay)
  double per_bucket;    // occluder buckets per m² of tangent2
  bool probe;           // a crowd: pairs test their sector's blocker first
  double near_tier2;    // m², robots farther than this (centre) go to the far tier
  double far_tangent2;  // m², no far robot's circle has a smaller tangent2 (with margin)
  const Media* m;
};

/// One pair: the segment from device a to partner b and where b's circle starts on it.
struct Pair {
  int partner;
  Vec2 from, to;
  double dx, dy, dd;  // to - from and its squared length
  double t_partner;   // fraction where the partner's circle is entered
};

bool SpansHeight(const ObstacleDef& o, double z) { return z >= o.z && z <= o.z + o.height; }

/// Whether obstacle k's bounding box misses the box [lo, hi] of a segment.
bool BoxesMiss(const Media& m, int k, const Vec2& lo, const Vec2& hi) {
  const Vec2 &olo = m.obstacle_lo[k], &ohi = m.obstacle_hi[k];
  return hi.x() < olo.x() || lo.x() > ohi.x() || hi.y() < olo.y() || lo.y() > ohi.y();
}

/// Serial part before the devices: members, grids. False when nobody can hear anybody.
bool Begin(const RobotStates& robots, Media* m) {
  const int n = static_cast<int>(robots.size());
  int count = 0;
  for (int i = 0; i < n; ++i) {
    m->rab_inbox[i].clear();
    m->rab_member[i] = m->rab_medium[i] >= 0 && robots[i].alive;
    count += m->rab_member[i];
  }
  if (count < 2) return false;
  m->rab_grid.FilePoints(n, [&](int i) { return m->body_xy[i]; });  // every body may occlude
  // Around each body, a circle holding it and its gripper disc: the disc's farthest centre
  // plus its radius, and 1e-6 m to spare (a segment's rounding is ~1e-15 m here).
  double disc_off2 = 0;
  for (int i = 0; i < n; ++i) disc_off2 = std::max(disc_off2, (m->gripper_xy[i] - m->body_xy[i]).squaredNorm());
  const double bound = std::max(footbot::kRadius, std::sqrt(disc_off2) + kGripperRadius) + 1e-6;
  m->rab_bound_radius2 = bound * bound;
  const int obstacles = static_cast<int>(m->obstacle_xy.size());
  if (obstacles > 0)
    m->rab_obstacle_grid.FileBoxes(
        obstacles, [&](int k) { return m->obstacle_lo[k]; }, [&](int k) { return m->obstacle_hi[k]; });
  return true;
}

/// The obstacles that may hide a pair of the device's: listed if few (rows of cells within
/// reach, each obstacle once), else each pair walks its own cells (walk_obstacles). A
/// segment from the device is shorter than the reach, so whatever it enters lies in these cells.
void GatherObstacles(const Model& model, const Media& m, const Device& d, RabScratch& scratch) {
  scratch.near_obstacles.clear();
  scratch.walk_obstacles = false;
  if (!d.occlusions || m.obstacle_xy.empty()) return;
  const UniformGrid& grid = m.rab_obstacle_grid;
  const double reach = m.rab_max_range;
  ++scratch.stamp;
  const int col0 = grid.Column(d.xy.x() - reach), col1 = grid.Column(d.xy.x() + reach);
  for (int row = grid.Row(d.xy.y() - reach), row1 = grid.Row(d.xy.y() + reach); row <= row1; ++row)
    for (int k : grid.RowItems(row, col0, col1)) {
      if (scratch.obstacle_stamp[k] == scratch.stamp) continue;
      scratch.obstacle_stamp[k] = scratch.stamp;
      if (!SpansHeight(model.obstacles[k], d.pos.z())) continue;
      if (static_cast<int>(scratch.near_obstacles.size()) == rab::kFewObstacles) {
        scratch.walk_obstacles = true;
        return;
      }
      scratch.near_obstacles.push_back(k);
    }
}

/// A circle's squared tangent length from the device if it may hide a pair: not around the
/// device (Box2D reports no hit for a ray starting inside) and within reach; else +inf,
/// which no segment enters (Enters).
double Tangent2(double n2, double radius2, double near2) {
  const double tangent2 = n2 - radius2;
  return tangent2 < 0 || tangent2 > near2 ? std::numeric_limits<double>::infinity() : tangent2;
}

/// Robot j as an occluder of the device into *o (its body, and the gripper disc ahead of
/// it: a third robot's hides a pair too), given the body's offset; false if neither may
/// hide a pair. CircleEntry(from, to, centre, r) split: the offset and tangent2 depend on
/// the circle only (same operations, so the same bits: the build has -ffp-contract=off).
[[gnu::always_inline]] inline bool MakeOccluder(const Device& d, int j, double sx, double sy, double n2,
                                                RabOccluder* o) {
  const Media& m = *d.m;
  const double near = m.rab_max_range + footbot::kRadius;  // a body touching a segment from a is this close
  const double near2 = near * near;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double tangent2 = n2 <= near2 ? Tangent2(n2, kBodyRadius2, near2) : kInf;
  const Vec2& g = m.gripper_xy[j];
  const double gx = g.x() - d.xy.x(), gy = g.y() - d.xy.y();
  const double disc_tangent2 = Tangent2(gx * gx + gy * gy, kGripperRadius * kGripperRadius, near2);
  const double nearest = std::min(tangent2, disc_tangent2);
  if (nearest == kInf) return false;
  const double q = nearest * d.per_bucket;
  const int bucket = q < rab::kOccluderBuckets ? static_cast<int>(q) : rab::kOccluderBuckets - 1;
  *o = {n2 - m.rab_bound_radius2, sx, sy, tangent2, gx, gy, disc_tangent2, j, bucket};
  return true;
}

/// One pass over the bodies near the device: the candidate partners (members after it, any
/// order: the partners are sorted at the end) and, unsorted, the near tier's occluders (any
/// other robot whose body or gripper disc may hide a pair); the far tier's robots are only
/// listed. Returns the number of near occluders.
int GatherNeighbours(const Device& d, RabScratch& scratch) {
  const Media& m = *d.m;
  const double near = m.rab_max_range + footbot::kRadius;
  const double near2 = near * near;
  // A gripper disc lies within the body radius plus its own of its robot's centre.
  const double reach = near + kGripperRadius;
  const bool body_occluders = d.occlusions && d.bodies_occlude;
  scratch.candidates.clear();
  scratch.far.clear();
  scratch.far_ready = false;
  int occluders = 0;
  m.rab_grid.ForEachInBox(d.xy.x() - reach, d.xy.y() - reach, d.xy.x() + reach, d.xy.y() + reach, [&](int j) {
    if (j == d.index) return;  // the sender's own shapes never hide (ARGoS skips its body)
    const Vec2& xj = m.body_xy[j];
    const double sx = xj.x() - d.xy.x(), sy = xj.y() - d.xy.y();
    const double n2 = sx * sx + sy * sy;
    if (n2 <= near2 && j > d.index && m.rab_member[j]) scratch.candidates.push_back(j);
    if (!body_occluders) return;
    if (n2 > d.near_tier2)
      scratch.far.push_back(j);
    else
      occluders += MakeOccluder(d, j, sx, sy, n2, &scratch.unsorted[occluders]);
  });
  return occluders;
}

/// The far tier's occluders after the near tier's `first`, bucketed alike (slots absolute).
void BuildFarTier(const Device& d, int first, RabScratch& scratch) {
  int count = 0;
  for (int j : scratch.far) {
    const Vec2& xj = d.m->body_xy[j];
    const double sx = xj.x() - d.xy.x(), sy = xj.y() - d.xy.y();
    count += MakeOccluder(d, j, sx, sy, sx * sx + sy * sy, &scratch.unsorted[count]);
  }
  BucketSort(
      count, &scratch.far_bucket_start, [&](int i, auto&& file) { file(scratch.unsorted[i].bucket); },
      [&](int slot, int i) { scratch.occluders[first + slot] = scratch.unsorted[i]; });
  for (int& start : scratch.far_bucket_start) start += first;
  scratch.far_ready = true;
}

/// Occluders bucketed by tangent2 (a counting sort, not a comparison sort): a pair only
/// scans the buckets up to its cut-off, nearest first.
void SortOccluders(int occluders, RabScratch& scratch) {
  BucketSort(
      occluders, &scratch.bucket_start, [&](int i, auto&& file) { file(scratch.unsorted[i].bucket); },
      [&](int slot, int i) { scratch.occluders[slot] = scratch.unsorted[i]; });
}

/// Blockers from the bodies within kBlockerReach only (farther ones rarely cover a
/// sector), and only in a crowd: elsewhere most pairs are unhidden, probes would not pay.
bool ProbeBlockers(const Device& d, int occluders, RabScratch& scratch) {
  const double reach_bucket = (rab::kBlockerReach * rab::kBlockerReach - kBodyRadius2) * d.per_bucket;
  const int within =
      reach_bucket < rab::kOccluderBuckets ? scratch.bucket_start[static_cast<int>(reach_bucket) + 1] : occluders;
  if (within < rab::kCrowd) return false;
  rab_blockers::FindBlockers(scratch, within);
  return true;
}

/// Whether a circle is entered before the partner's: the rest of CircleEntry(from, to,
/// centre, r) < t_partner (t_partner <= 1, so "t in [0, 1]" reduces to t >= 0), given
/// along = offset · (to - from).
[[gnu::always_inline]] inline bool EntersCircle(double along, double tangent2, const Pair& p) {
  const double disc = along * along - p.dd * tangent2;
  if (disc < 0) return false;
  const double t = (along - std::sqrt(disc)) / p.dd;
  return t >= 0 && t < p.t_partner;
}

/// Whether the robot's body or gripper disc is entered before the partner's. A segment's
/// line that misses the circle around both (bound2) misses each: for the body, bound2 <=
/// tangent2 with the same along, so its disc can only be larger (rounding is monotone);
/// for the disc, by the bound's margin. Inlined: a call per occluder was a sixth of the
/// routing's instructions.
[[gnu::always_inline]] inline bool Enters(const RabOccluder& o, const Pair& p) {
  const double along = o.offset_x * p.dx + o.offset_y * p.dy;
  if (along * along - p.dd * o.bound2 < 0 || o.body == p.partner) return false;
  return EntersCircle(along, o.tangent2, p) || EntersCircle(o.disc_x * p.dx + o.disc_y * p.dy, o.disc_tangent2, p);
}

/// Whether an occluder of slots [begin, end) hides the pair; the first that does becomes
/// the blocker.
bool ScanOccluders(const RabScratch& scratch, int begin, int end, const Pair& p, int& blocker) {
  for (int i = begin; i < end; ++i)
    if (Enters(scratch.occluders[i], p)) {
      blocker = i;  // a likelier guess for the next pairs of its sector
      return true;
    }
  return false;
}

/// The slot past the buckets up to q's, given a tier's bucket starts and size.
int ScanLimit(double q, const std::vector<int>& start, int end) {
  return !(q >= 0) ? start[0] : q < rab::kOccluderBuckets ? start[static_cast<int>(q) + 1] : end;
}

/// The first body along the pair's segment must be the partner's: any occluder entered
/// before it hides it. Its sector's blocker first (it hides most pairs of a crowd), then
/// all, nearest first, up to the bucket past which no centre is closer than the partner's:
/// the near tier, then the far one if that bound reaches it.
bool HiddenByBody(const Device& d, const Pair& p, int occluders, RabScratch& scratch) {
  if (!(p.dd > 0)) return false;
  // A body entered before t_partner has its centre closer than the partner's: |s| < len,
  // so tangent2 < dd - r². The scan stops after the bucket of that bound (with a relative
  // margin far above rounding: the test itself stays exact; scanning more is safe).
  const double tangent2_max = (p.dd - kBodyRadius2) * (1 + 1e-9) + 1e-12;
  const double q = tangent2_max * d.per_bucket;  // monotone in tangent2: its bucket bounds theirs
  int no_blocker = -1;
  int& blocker =
      d.probe ? scratch.sector_blocker[rab_blockers::SectorOf(rab_blockers::PseudoAngle(p.dx, p.dy))] : no_blocker;
  if (blocker >= 0 && Enters(scratch.occluders[blocker], p)) return true;
  if (ScanOccluders(scratch, 0, ScanLimit(q, scratch.bucket_start, occluders), p, blocker)) return true;
  if (!(tangent2_max >= d.far_tangent2) || scratch.far.empty()) return false;
  if (!scratch.far_ready) BuildFarTier(d, occluders, scratch);
  const int end = scratch.far_bucket_start[rab::kOccluderBuckets];
  return ScanOccluders(scratch, occluders, ScanLimit(q, scratch.far_bucket_start, end), p, blocker);
}

/// Whether segment a -> b enters an obstacle spanning height z before fraction t_b. Only
/// the obstacles listed in the cells the segment crosses can: it walks them row by row,
/// each row over the segment's x span within it. Spans are widened far beyond rounding (an
/// extra cell costs a little; every cell of a point of the segment is visited). An
/// obstacle in several of these cells is tested in each: the answer is the same.
bool WalkObstacles(const Model& model, const Media& m, const Vec2& a, const Vec2& b, double t_b, double z) {
  const UniformGrid& g = m.rab_obstacle_grid;
  const Vec2 lo = a.cwiseMin(b), hi = a.cwiseMax(b);
  const double eps = 1e-9 * (lo.cwiseAbs().maxCoeff() + hi.cwiseAbs().maxCoeff() + g.CellSize()) + 1e-12;
  const double dx = b.x() - a.x(), dy = b.y() - a.y();
  const int x0 = g.Column(lo.x() - eps), x1 = g.Column(hi.x() + eps);
  const int y0 = g.Row(lo.y() - eps), y1 = g.Row(hi.y() + eps);
  for (int row = y0; row <= y1; ++row) {
    int col0 = x0, col1 = x1;
    if (y0 < y1 && dy != 0) {
      // The row's band (open-ended at the grid's edges, where points outside land).
      constexpr double kInf = std::numeric_limits<double>::infinity();
      const double band_lo = row == 0 ? -kInf : g.Origin().y() + row * g.CellSize() - eps;
      const double band_hi = row == g.Rows() - 1 ? kInf : g.Origin().y() + (row + 1) * g.CellSize() + eps;
      double t0 = (band_lo - a.y()) / dy, t1 = (band_hi - a.y()) / dy;
      if (t0 > t1) std::swap(t0, t1);
      t0 = std::max(t0, 0.0), t1 = std::min(t1, 1.0);
      if (t0 > t1) continue;
      const double xa = a.x() + t0 * dx, xb = a.x() + t1 * dx;
      col0 = std::max(x0, g.Column(std::min(xa, xb) - eps));
      col1 = std::min(x1, g.Column(std::max(xa, xb) + eps));
      if (col0 > col1) continue;
    }
    for (int k : g.RowItems(row, col0, col1)) {
      const ObstacleDef& o = model.obstacles[k];
      if (!SpansHeight(o, z) || BoxesMiss(m, k, lo, hi)) continue;
      if (ObstacleEntry(o, m, k, a, b) < t_b) return true;
    }
  }
  return false;
}

/// Whether a box or cylinder is entered before the partner's circle.
bool HiddenByObstacle(const Model& model, const Media& m, const Device& d, const Pair& p, const RabScratch& scratch) {
  if (scratch.walk_obstacles) return WalkObstacles(model, m, p.from, p.to, p.t_partner, d.pos.z());
  const Vec2 lo = p.from.cwiseMin(p.to), hi = p.from.cwiseMax(p.to);
  for (int k : scratch.near_obstacles) {
    if (BoxesMiss(m, k, lo, hi)) continue;
    if (ObstacleEntry(model.obstacles[k], m, k, p.from, p.to) < p.t_partner) return true;
  }
  return false;
}

Pair MakePair(const Media& m, const Device& d, int partner, const Vec3& partner_pos) {
  Pair p;
  p.partner = partner;
  p.from = d.xy;
  p.to = partner_pos.head<2>();
  const double len = (p.to - p.from).norm();
  p.t_partner = len > 0 ? std::max(0.0, len - footbot::kRadius) / len : 0.0;
  // The partner's gripper disc, when it faces the device, is the partner's first shape met.
  p.t_partner = std::min(p.t_partner, CircleEntry(p.from, p.to, m.gripper_xy[partner], kGripperRadius));
  p.dx = p.to.x() - p.from.x();
  p.dy = p.to.y() - p.from.y();
  p.dd = p.dx * p.dx + p.dy * p.dy;
  return p;
}

/// The device's partners among the candidates: same medium and packet size, in range one
/// way or both (the sender's range, strict), not hidden. Each as b << 2 | (a hears b) |
/// (b hears a) << 1, sorted by b so that every inbox ends up in sender order.
void Deliverable(const Model& model, const Media& m, const Device& d, int occluders, RabScratch& scratch,
                 std::vector<int>* out) {
  const RobotDef& da = model.robots[d.index];
  for (int b : scratch.candidates) {
    const RobotDef& db = model.robots[b];
    if (m.rab_medium[b] != m.rab_medium[d.index] || db.rab_data_size != da.rab_data_size) continue;
    const Vec3& pb = m.rab_pos[b];
    const double dist = (pb - d.pos).norm();
    const bool a_hears_b = dist < db.rab_range;
    const bool b_hears_a = dist < da.rab_range;
    if (!a_hears_b && !b_hears_a) continue;
    if (d.occlusions) {
      const Pair p = MakePair(m, d, b, pb);
      if (d.bodies_occlude && HiddenByBody(d, p, occluders, scratch)) continue;
      if (HiddenByObstacle(model, m, d, p, scratch)) continue;
    }
    out->push_back(b << 2 | static_cast<int>(a_hears_b) | static_cast<int>(b_hears_a) << 1);
  }
  std::sort(out->begin(), out->end());
}

/// Device a's unhidden partners b > a into m->rab_partners[a]. Reads the shared media,
/// writes only a's list and the scratch: devices run concurrently.
void RouteDevice(const Model& model, Media* m, int a, RabScratch& scratch) {
  std::vector<int>& out = m->rab_partners[a];
  out.clear();
  if (!m->rab_member[a]) return;
  Device d;
  d.index = a;
  d.pos = m->rab_pos[a];
  d.xy = d.pos.head<2>();
  d.occlusions = model.rab_media[m->rab_medium[a]].check_occlusions;
  d.bodies_occlude = d.pos.z() >= 0 && d.pos.z() <= footbot::kHeight;
  const double near = m->rab_max_range + footbot::kRadius;
  d.per_bucket = rab::kOccluderBuckets / (near * near);  // tangent2 < near²
  d.probe = false;
  d.m = m;
  // Far robots' centres are beyond the near tier's radius, so their circles (within the
  // bound radius of the centre) have tangent2 >= (radius - bound)², less a margin far
  // above rounding.
  const double tier = std::max(rab::kBlockerReach + 0.1, rab::kNearTier * near);
  const double gap = std::max(0.0, tier - std::sqrt(m->rab_bound_radius2));
  d.near_tier2 = tier * tier;
  d.far_tangent2 = gap * gap * (1 - 1e-9) - 1e-12;
  GatherObstacles(model, *m, d, scratch);
  const int occluders = GatherNeighbours(d, scratch);
  if (d.occlusions && d.bodies_occlude) {
    SortOccluders(occluders, scratch);
    d.probe = ProbeBlockers(d, occluders, scratch);
  }
  Deliverable(model, *m, d, occluders, scratch, &out);
}

/// Serial part after the devices: partners into inboxes in ascending a, so inbox r lists
/// its senders a < r (appended as a rises) then its own partners b > r, ascending.
void Deliver(Media* m) {
  const int n = static_cast<int>(m->rab_partners.size());
  for (int a = 0; a < n; ++a)
    for (int e : m->rab_partners[a]) {
      const int b = e >> 2;
      if (e & 1) m->rab_inbox[a].push_back(b);
      if (e & 2) m->rab_inbox[b].push_back(a);
    }
}

/// Sizes a slot's scratch for the model (first tick, or after InitMedia).
void SizeScratch(const Model& model, RabScratch* scratch) {
  const size_t n = model.robots.size();
  scratch->candidates.reserve(n);
  scratch->unsorted.resize(n);  // a robot each (its body and gripper disc)
  scratch->occluders.resize(n);
  scratch->bucket_start.assign(rab::kOccluderBuckets + 1, 0);
  scratch->far_bucket_start.assign(rab::kOccluderBuckets + 1, 0);
  scratch->far.reserve(n);
  scratch->sector_blocker.assign(rab::kProbeSectors, -1);
  scratch->near_obstacles.reserve(rab::kFewObstacles);
  scratch->obstacle_stamp.assign(model.obstacles.size(), 0);
  scratch->stamp = 0;
}

struct RouteJob {
  const Model* model;
  Media* media;
  int slots;
};

void RouteSlot(void* ctx, int slot) {
  const RouteJob& job = *static_cast<const RouteJob*>(ctx);
  RabScratch& scratch = job.media->rab_scratch[slot];
  const int n = static_cast<int>(job.media->rab_partners.size());
  // Interleaved devices: low indices have more partners b > a, so contiguous ranges would
  // not balance. Which slot routes a device does not change its list.
  for (int a = slot; a < n; a += job.slots) RouteDevice(*job.model, job.media, a, scratch);
}

}  // namespace

void InitRabRouting(const Model& model, Media* m) {
  const size_t n = model.robots.size();
  m->rab_inbox.resize(n);
  m->rab_medium.assign(n, -1);
  m->rab_member.assign(n, 0);
  m->rab_pos.assign(n, Vec3::Zero());
  m->rab_yaw.assign(n, 0);
  m->rab_partners.resize(n);
  m->rab_scratch.clear();  // sized by RouteRab for its runner's slots
  m->rab_max_range = 0;
  m->rab_devices = 0;
  for (size_t i = 0; i < n; ++i) {
    // Only the sensor puts a robot in the RAB medium (an ARGoS quirk, docs/compatibility.md).
    const DeviceConfig* d = model.controllers[model.robots[i].controller].Find(DeviceType::RabSensor);
    if (!d) continue;
    m->rab_medium[i] = MediumIndex(model.rab_media, d->Attr("medium"));
    if (m->rab_medium[i] < 0) continue;
    ++m->rab_devices;
    m->rab_max_range = std::max(m->rab_max_range, model.robots[i].rab_range);
    if (m->rab_inbox[i].capacity() < 16) m->rab_inbox[i].reserve(std::min<size_t>(n, 64));
    if (m->rab_partners[i].capacity() < 16) m->rab_partners[i].reserve(std::min<size_t>(n, 64));
  }
  if (m->rab_devices < 2) return;
  // Over the arena (points outside fall into the border cells), cells of the reach, so a
  // device looks at 3x3 cells. Obstacles by bounding box in every cell it overlaps; cells of
  // about a quarter of the reach, so that a pair's segment visits few cells and each lists
  // few obstacles.
  const Vec2 lo = model.arena.Min(), hi = model.arena.Max();
  const double near = m->rab_max_range + footbot::kRadius;
  m->rab_grid.CoverBox(lo, hi, near, 4 * n + 64);
  m->rab_grid.Reserve(n, n);
  CoverObstacles(lo, hi, near / 4, 0.5, *m, &m->rab_obstacle_grid);
}

void RouteRab(const Model& model, const RobotStates& robots, Media* m, const SlotRunner& runner) {
  if (m->rab_devices < 2 || !Begin(robots, m)) return;
  // A few devices are not worth waking the threads for (the result is the same).
  const int slots = runner.run && m->rab_devices >= 64 ? std::max(1, runner.slots) : 1;
  if (static_cast<int>(m->rab_scratch.size()) < slots) {  // first tick: allocates once
    m->rab_scratch.resize(slots);
    for (RabScratch& scratch : m->rab_scratch) SizeScratch(model, &scratch);
  }
  RouteJob job{&model, m, slots};
  if (slots > 1)
    runner.run(runner.pool, RouteSlot, &job);
  else
    RouteSlot(&job, 0);
  Deliver(m);
}

}  // namespace essaim
