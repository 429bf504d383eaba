// Media stage (spec §12 step 4): after physics, before any robot senses.
// Range and bearing: who hears whom. Candidates come from a uniform grid of all robot
// bodies with cells of the largest rab_range (a device looks at the 3x3 cells around it:
// never all pairs). Occlusion uses exact circle and box tests against the bodies and
// obstacles near the device: what one Box2D ray per pair would find, without walking
// Box2D's tree for every pair. Devices are routed in parallel (each lists its partners
// b > a with its thread's scratch), then one serial pass fills the inboxes in ascending a:
// the same inboxes, in the same order, at any thread count.
// LEDs: the lit LEDs of robots, boxes/cylinders and <light>s, bucketed in a grid that
// the cameras query, plus grids of bodies and obstacles for their occlusion rays.
// Every buffer is sized by InitMedia; a tick allocates nothing.
#include "devices/media.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "devices/rab_blockers.h"

namespace essaim {

// ---------------------------------------------------------------- PointGrid

void PointGrid::Setup(const Vec2& min, const Vec2& max, double cell_size, size_t max_items, size_t max_cells) {
  origin = min;
  Vec2 ext = (max - min).cwiseMax(Vec2(1e-3, 1e-3));
  if (!(cell_size > 1e-3)) cell_size = 1e-3;  // also catches NaN
  cell_size = std::min(cell_size, std::max(ext.x(), ext.y()));
  max_cells = std::max<size_t>(max_cells, 1);
  for (;;) {
    nx = std::max(1, static_cast<int>(std::ceil(ext.x() / cell_size)));
    ny = std::max(1, static_cast<int>(std::ceil(ext.y() / cell_size)));
    if (static_cast<size_t>(nx) * ny <= max_cells) break;
    cell_size *= 1.5;
  }
  cell = cell_size;
  cell_start.assign(static_cast<size_t>(nx) * ny + 1, 0);
  items.assign(max_items, 0);
  cell_of.assign(max_items, 0);
}

size_t PointGrid::DiscEntries(double radius) const {
  const size_t span = static_cast<size_t>(std::ceil(2 * radius / cell)) + 1;
  return std::min<size_t>(span, nx) * std::min<size_t>(span, ny);
}

template <class PosFn>
void PointGrid::Build(int n, PosFn pos) {
  // Counting sort: counts, inclusive prefix sums (= cell ends), then fill backwards so
  // each cell lists its points in ascending order and cell_start[c] ends as its start.
  std::fill(cell_start.begin(), cell_start.end(), 0);
  for (int i = 0; i < n; ++i) {
    Vec2 p = pos(i);
    int c = CellY(p.y()) * nx + CellX(p.x());
    cell_of[i] = c;
    ++cell_start[c];
  }
  const size_t cells = cell_start.size() - 1;
  for (size_t c = 1; c < cells; ++c) cell_start[c] += cell_start[c - 1];
  cell_start[cells] = n;
  for (int i = n - 1; i >= 0; --i) items[--cell_start[cell_of[i]]] = i;
}

template <class PosFn, class RadiusFn>
void PointGrid::BuildDiscs(int n, PosFn pos, RadiusFn radius) {
  // Each disc over the cells of its bounding box.
  BuildBoxes(n, [&](int i) { return Vec2(pos(i).array() - radius(i)); },
             [&](int i) { return Vec2(pos(i).array() + radius(i)); });
}

template <class LoFn, class HiFn>
void PointGrid::BuildBoxes(int n, LoFn lo, HiFn hi) {
  // As Build, over each box's cells: count, prefix sums, fill backwards.
  std::fill(cell_start.begin(), cell_start.end(), 0);
  auto each_cell = [&](int i, auto&& f) {
    const Vec2 a = lo(i), b = hi(i);
    for (int cy = CellY(a.y()), y1 = CellY(b.y()); cy <= y1; ++cy)
      for (int cx = CellX(a.x()), x1 = CellX(b.x()); cx <= x1; ++cx) f(cy * nx + cx);
  };
  int total = 0;
  for (int i = 0; i < n; ++i) each_cell(i, [&](int c) { ++cell_start[c], ++total; });
  // Setup's bound has a spare cell per axis; only absurd coordinates (margins of a cell) get here.
  if (static_cast<size_t>(total) > items.size()) items.resize(total);
  const size_t cells = cell_start.size() - 1;
  for (size_t c = 1; c < cells; ++c) cell_start[c] += cell_start[c - 1];
  cell_start[cells] = total;
  for (int i = n - 1; i >= 0; --i) each_cell(i, [&](int c) { items[--cell_start[c]] = i; });
}

// ---------------------------------------------------------------- geometry

Vec3 FootBotLedPosition(const Pose2& pose, double z, double turret, int i) {
  constexpr double kRingRadius = 0.090036758;  // body radius + 5 mm (spec §1.1)
  constexpr double kRingElevation = 0.085;
  constexpr double kBeaconElevation = 0.174249733;
  if (i >= 12) return Vec3(pose.x, pose.y, z + kBeaconElevation);
  double a = pose.yaw + turret + DegToRad(15.0 + 30.0 * i);
  return Vec3(pose.x + kRingRadius * std::cos(a), pose.y + kRingRadius * std::sin(a), z + kRingElevation);
}

double BoxEntry(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& cs, double hx, double hy) {
  // b2PolygonShape::RayCast in the box frame: clip [0, 1] by the four edges; a hit needs
  // an entering edge (a segment starting inside reports nothing).
  const Vec2 ra = a - c, rb = b - c;
  const Vec2 p(cs.x() * ra.x() + cs.y() * ra.y(), -cs.y() * ra.x() + cs.x() * ra.y());
  const Vec2 q(cs.x() * rb.x() + cs.y() * rb.y(), -cs.y() * rb.x() + cs.x() * rb.y());
  const Vec2 d = q - p;
  double lower = 0, upper = 1;
  bool entered = false;
  const double h[2] = {hx, hy};
  for (int k = 0; k < 2; ++k) {
    for (double side : {-1.0, 1.0}) {
      const double num = h[k] - side * p[k];  // edge with outward normal side·e_k
      const double den = side * d[k];
      if (den == 0) {
        if (num < 0) return 2;
      } else if (den < 0 && num < lower * den) {
        lower = num / den;
        entered = true;
      } else if (den > 0 && num < upper * den) {
        upper = num / den;
      }
      if (upper < lower) return 2;
    }
  }
  return entered ? lower : 2;
}

namespace {
double ObstacleEntry(const ObstacleDef& o, const Media& m, int k, const Vec2& a, const Vec2& b) {
  return o.kind == ShapeKind::Cylinder ? CircleEntry(a, b, m.obstacle_xy[k], o.radius)
                                       : BoxEntry(a, b, m.obstacle_xy[k], m.obstacle_cs[k], o.size_x / 2, o.size_y / 2);
}
}  // namespace

bool CameraRayBlocked(const Model& model, const Media& m, const Vec2& a, const Vec2& b, double z, int exclude_robot,
                      int skip_obstacle) {
  const Vec2 lo = a.cwiseMin(b), hi = a.cwiseMax(b);
  if (z >= 0 && z <= footbot::kHeight) {  // robots reach this height (PhysicsWorld::CastRay)
    const PointGrid& g = m.camera_body_grid;
    const double r = footbot::kRadius;
    for (int cy = g.CellY(lo.y() - r), y1 = g.CellY(hi.y() + r); cy <= y1; ++cy)
      for (int cx = g.CellX(lo.x() - r), x1 = g.CellX(hi.x() + r); cx <= x1; ++cx) {
        const int c = cy * g.nx + cx;
        for (int s = g.cell_start[c]; s < g.cell_start[c + 1]; ++s) {
          const int j = g.items[s];
          if (j != exclude_robot && CircleEntry(a, b, m.body_xy[j], r) <= 1) return true;
        }
      }
  }
  if (m.obstacle_xy.empty()) return false;
  const PointGrid& g = m.camera_obstacle_grid;  // obstacles sit in every cell they overlap
  for (int cy = g.CellY(lo.y()), y1 = g.CellY(hi.y()); cy <= y1; ++cy)
    for (int cx = g.CellX(lo.x()), x1 = g.CellX(hi.x()); cx <= x1; ++cx) {
      const int c = cy * g.nx + cx;
      for (int s = g.cell_start[c]; s < g.cell_start[c + 1]; ++s) {
        const int k = g.items[s];
        const ObstacleDef& o = model.obstacles[k];
        if (k == skip_obstacle || z < o.z || z > o.z + o.height) continue;
        if (ObstacleEntry(o, m, k, a, b) <= 1) return true;
      }
    }
  return false;
}

namespace {
template <class Def>
int MediumIndex(const std::vector<Def>& media, const std::string& id) {
  for (size_t k = 0; k < media.size(); ++k)
    if (media[k].id == id) return static_cast<int>(k);
  return -1;
}

/// ARGoS compares colours with alpha: only (0,0,0,255) is "black", i.e. off (spec §7.1).
bool LedOff(const Color& c) { return c == Color(); }

/// Serial part before the devices: members, grids. False when nobody can hear anybody.
bool RabBegin(const std::vector<RobotState>& robots, Media* m) {
  const int n = static_cast<int>(robots.size());
  int count = 0;
  for (int i = 0; i < n; ++i) {
    m->rab_inbox[i].clear();
    m->rab_member[i] = m->rab_medium[i] >= 0 && robots[i].alive;
    count += m->rab_member[i];
  }
  if (count < 2) return false;
  m->rab_grid.Build(n, [&](int i) { return m->body_xy[i]; });  // every body may occlude
  const int n_obs = static_cast<int>(m->obstacle_xy.size());
  if (n_obs > 0)
    m->rab_obstacle_grid.BuildBoxes(n_obs, [&](int k) { return m->obstacle_lo[k]; },
                                    [&](int k) { return m->obstacle_hi[k]; });
  return true;
}

/// Whether segment a -> b enters an obstacle spanning height z before fraction t_b. Only
/// the obstacles listed in the cells the segment crosses can: it walks them row by row,
/// each row over the segment's x span within it. Spans are widened far beyond rounding (an
/// extra cell costs a little; every cell of a point of the segment is visited). An
/// obstacle in several of these cells is tested in each: the answer is the same.
bool ObstacleHides(const Model& model, const Media& m, const Vec2& a, const Vec2& b, double t_b, double z) {
  const PointGrid& g = m.rab_obstacle_grid;
  const Vec2 lo = a.cwiseMin(b), hi = a.cwiseMax(b);
  const double eps = 1e-9 * (lo.cwiseAbs().maxCoeff() + hi.cwiseAbs().maxCoeff() + g.cell) + 1e-12;
  const double dx = b.x() - a.x(), dy = b.y() - a.y();
  const int x0 = g.CellX(lo.x() - eps), x1 = g.CellX(hi.x() + eps);
  const int y0 = g.CellY(lo.y() - eps), y1 = g.CellY(hi.y() + eps);
  for (int cy = y0; cy <= y1; ++cy) {
    int cx0 = x0, cx1 = x1;
    if (y0 < y1 && dy != 0) {
      // The row's band (open-ended at the grid's edges, where points outside land).
      constexpr double kInf = std::numeric_limits<double>::infinity();
      const double band_lo = cy == 0 ? -kInf : g.origin.y() + cy * g.cell - eps;
      const double band_hi = cy == g.ny - 1 ? kInf : g.origin.y() + (cy + 1) * g.cell + eps;
      double t0 = (band_lo - a.y()) / dy, t1 = (band_hi - a.y()) / dy;
      if (t0 > t1) std::swap(t0, t1);
      t0 = std::max(t0, 0.0), t1 = std::min(t1, 1.0);
      if (t0 > t1) continue;
      const double xa = a.x() + t0 * dx, xb = a.x() + t1 * dx;
      cx0 = std::max(x0, g.CellX(std::min(xa, xb) - eps));
      cx1 = std::min(x1, g.CellX(std::max(xa, xb) + eps));
    }
    // Cells cx0..cx1 of a row are consecutive in the grid: their items are one range.
    for (int s = g.cell_start[cy * g.nx + cx0], end = g.cell_start[cy * g.nx + cx1 + 1]; s < end; ++s) {
      const int k = g.items[s];
      const ObstacleDef& o = model.obstacles[k];
      if (z < o.z || z > o.z + o.height) continue;
      const Vec2 &olo = m.obstacle_lo[k], &ohi = m.obstacle_hi[k];
      if (hi.x() < olo.x() || lo.x() > ohi.x() || hi.y() < olo.y() || lo.y() > ohi.y()) continue;
      if (ObstacleEntry(o, m, k, a, b) < t_b) return true;
    }
  }
  return false;
}

/// Device a's unhidden partners b > a into m->rab_partners[a]. Reads the shared media,
/// writes only a's list and the scratch: devices run concurrently.
void RabPartners(const Model& model, Media* m, int a, Media::RabScratch& sc) {
  std::vector<int>& out = m->rab_partners[a];
  out.clear();
  if (!m->rab_member[a]) return;
  const PointGrid& g = m->rab_grid;
  const int n_obs = static_cast<int>(m->obstacle_xy.size());
  const Vec3& pa = m->rab_pos[a];
  const Vec2 xa = pa.head<2>();
  const RobotDef& da = model.robots[a];
  const bool occlusions = model.rab_media[m->rab_medium[a]].check_occlusions;
  const double reach = m->rab_max_range;
  const double near = reach + footbot::kRadius;  // a body touching a segment from a is this close
  // Obstacles that may hide a pair of a's: listed if few (rows of cells within reach, each
  // obstacle once), else each pair walks its own cells (walk_obstacles). A segment from a is
  // shorter than the reach, so whatever it enters lies in these cells.
  sc.near_obstacles.clear();
  bool walk_obstacles = false;
  if (occlusions && n_obs > 0) {
    const PointGrid& og = m->rab_obstacle_grid;
    ++sc.stamp;
    const int x0 = og.CellX(xa.x() - reach), x1 = og.CellX(xa.x() + reach);
    for (int cy = og.CellY(xa.y() - reach), y1 = og.CellY(xa.y() + reach); cy <= y1 && !walk_obstacles; ++cy)
      for (int s = og.cell_start[cy * og.nx + x0], end = og.cell_start[cy * og.nx + x1 + 1]; s < end; ++s) {
        const int k = og.items[s];
        if (sc.obstacle_stamp[k] == sc.stamp) continue;
        sc.obstacle_stamp[k] = sc.stamp;
        const ObstacleDef& o = model.obstacles[k];
        if (pa.z() < o.z || pa.z() > o.z + o.height) continue;
        if (static_cast<int>(sc.near_obstacles.size()) == Media::kFewObstacles) {
          walk_obstacles = true;
          break;
        }
        sc.near_obstacles.push_back(k);
      }
  }
  const bool bodies_occlude = pa.z() >= 0 && pa.z() <= footbot::kHeight;  // as CastRay
  const bool body_occluders = occlusions && bodies_occlude;
  // Occluders bucketed by cc (a counting sort, not a comparison sort): a pair only scans
  // the buckets up to its cut-off (see the pair loop), nearest first.
  constexpr int kBuckets = Media::kOccluderBuckets;
  const double near2 = near * near;
  const double per_bucket = kBuckets / near2;  // cc < near²
  const double r2 = footbot::kRadius * footbot::kRadius;
  if (body_occluders) std::fill(sc.bucket_end.begin(), sc.bucket_end.end(), 0);
  // One pass over the bodies near a: the candidate partners (members after a, any order:
  // the partners are sorted at the end) and the occluders (any other body but those around
  // a, cc < 0: Box2D reports no hit for a ray starting inside). CircleEntry(xa, xb, c, r)
  // split: s = c - a and cc = |s|² - r² depend on the occluder only (same operations, so
  // the same bits: the build has -ffp-contract=off).
  sc.near.clear();
  int n_occ = 0;
  for (int cy = g.CellY(xa.y() - near), y1 = g.CellY(xa.y() + near); cy <= y1; ++cy)
    for (int cx = g.CellX(xa.x() - near), x1 = g.CellX(xa.x() + near); cx <= x1; ++cx) {
      const int c = cy * g.nx + cx;
      for (int s = g.cell_start[c]; s < g.cell_start[c + 1]; ++s) {
        const int j = g.items[s];
        const Vec2& xj = m->body_xy[j];
        const double sx = xj.x() - xa.x(), sy = xj.y() - xa.y();
        const double n2 = sx * sx + sy * sy;
        if (n2 > near2 || j == a) continue;
        if (j > a && m->rab_member[j]) sc.near.push_back(j);
        const double cc = n2 - r2;
        if (!body_occluders || cc < 0) continue;
        const double q = cc * per_bucket;
        const int bucket = q < kBuckets ? static_cast<int>(q) : kBuckets - 1;
        sc.unsorted[n_occ++] = {cc, sx, sy, j, bucket};
        ++sc.bucket_end[bucket];
      }
    }
  if (body_occluders) {
    for (int k = 1; k < kBuckets; ++k) sc.bucket_end[k] += sc.bucket_end[k - 1];
    sc.bucket_end[kBuckets] = n_occ;
    // Fill backwards; bucket_end[k] ends as bucket k's start, so shift into ends after.
    for (int i = n_occ - 1; i >= 0; --i) sc.occluders[--sc.bucket_end[sc.unsorted[i].bucket]] = sc.unsorted[i];
    for (int k = 0; k < kBuckets; ++k) sc.bucket_end[k] = sc.bucket_end[k + 1];
  }
  // Blockers from the bodies within kBlockerReach only (farther ones rarely cover a
  // sector), and only in a crowd: elsewhere most pairs are unhidden, probes would not pay.
  bool probe = false;
  if (body_occluders) {
    const double qb = (Media::kBlockerReach * Media::kBlockerReach - r2) * per_bucket;
    const int n_blockers = qb < kBuckets ? sc.bucket_end[static_cast<int>(qb)] : n_occ;
    probe = n_blockers >= Media::kCrowd;
    if (probe) rab_blockers::FindBlockers(sc, n_blockers);
  }
  for (int b : sc.near) {
    const RobotDef& db = model.robots[b];
    if (m->rab_medium[b] != m->rab_medium[a] || db.rab_data_size != da.rab_data_size) continue;
    const Vec3& pb = m->rab_pos[b];
    const double d = (pb - pa).norm();
    const bool a_hears_b = d < db.rab_range;  // the sender's range, strict (spec §5.2)
    const bool b_hears_a = d < da.rab_range;
    if (!a_hears_b && !b_hears_a) continue;
    if (occlusions) {
      // The first body along a -> b's centre must be b's (spec §5.2): anything entered
      // before b's circle hides it.
      const Vec2 xb = pb.head<2>();
      const double len = (xb - xa).norm();
      const double t_b = len > 0 ? std::max(0.0, len - footbot::kRadius) / len : 0.0;
      bool hidden = false;
      if (bodies_occlude) {
        const double dx = xb.x() - xa.x(), dy = xb.y() - xa.y();
        const double dd = dx * dx + dy * dy;
        // A body entered before t_b has its centre closer to a than b's: |s| < len, so
        // cc < dd - r². The scan stops after the bucket of that bound (with a relative
        // margin far above rounding: the test itself stays exact; scanning more is safe).
        const double cc_max = (dd - footbot::kRadius * footbot::kRadius) * (1 + 1e-9) + 1e-12;
        const double q = cc_max * per_bucket;  // monotone in cc: its bucket bounds theirs
        const int limit = !(q >= 0) ? 0 : q < kBuckets ? sc.bucket_end[static_cast<int>(q)] : n_occ;
        // The rest of CircleEntry(xa, xb, body c, r) < t_b (t_b <= 1, so "t in [0, 1]"
        // reduces to t >= 0); the cheap tests reject almost every occluder before sqrt.
        auto enters = [&](const Media::NearBody& o) {
          const double bq = o.sx * dx + o.sy * dy;
          const double disc = bq * bq - dd * o.cc;
          if (disc < 0) return false;
          const double t = (bq - std::sqrt(disc)) / dd;
          return t >= 0 && t < t_b && o.body != b;
        };
        if (dd > 0) {
          // The sector's blocker first (it hides most pairs of a crowd), then all, nearest first.
          int no_blocker = -1;
          int& blocker = probe ? sc.sector_blocker[rab_blockers::SectorOf(rab_blockers::PseudoAngle(dx, dy))] : no_blocker;
          hidden = blocker >= 0 && enters(sc.occluders[blocker]);
          if (!hidden)
            for (int i = 0; i < limit; ++i)
              if (enters(sc.occluders[i])) {
                hidden = true;
                blocker = i;  // a likelier guess for the next pairs of its sector
                break;
              }
        }
      }
      if (!hidden && walk_obstacles) {
        hidden = ObstacleHides(model, *m, xa, xb, t_b, pa.z());
      } else if (!hidden) {
        const Vec2 lo = xa.cwiseMin(xb), hi = xa.cwiseMax(xb);
        for (int k : sc.near_obstacles) {
          const Vec2 &olo = m->obstacle_lo[k], &ohi = m->obstacle_hi[k];
          if (hi.x() < olo.x() || lo.x() > ohi.x() || hi.y() < olo.y() || lo.y() > ohi.y()) continue;
          if (ObstacleEntry(model.obstacles[k], *m, k, xa, xb) < t_b) {
            hidden = true;
            break;
          }
        }
      }
      if (hidden) continue;
    }
    out.push_back(b << 2 | static_cast<int>(a_hears_b) | static_cast<int>(b_hears_a) << 1);
  }
  std::sort(out.begin(), out.end());  // by b: every inbox ends up in sender order (spec §5.3)
}

/// Serial part after the devices: partners into inboxes in ascending a, so inbox r lists
/// its senders a < r (appended as a rises) then its own partners b > r, ascending.
void RabDeliver(Media* m) {
  const int n = static_cast<int>(m->rab_partners.size());
  for (int a = 0; a < n; ++a)
    for (int e : m->rab_partners[a]) {
      const int b = e >> 2;
      if (e & 1) m->rab_inbox[a].push_back(b);
      if (e & 2) m->rab_inbox[b].push_back(a);
    }
}

/// Sizes a slot's scratch for the model (first tick, or after InitMedia).
void SizeRabScratch(const Model& model, Media::RabScratch* sc) {
  const size_t n = model.robots.size();
  sc->near.reserve(n);
  sc->unsorted.resize(n);
  sc->occluders.resize(n);
  sc->bucket_end.assign(Media::kOccluderBuckets + 1, 0);
  sc->sector_blocker.assign(Media::kProbeSectors, -1);
  sc->near_obstacles.reserve(Media::kFewObstacles);
  sc->obstacle_stamp.assign(model.obstacles.size(), 0);
  sc->stamp = 0;
}

struct RabJob {
  const Model* model;
  Media* media;
  int slots;
};

void RabSlot(void* ctx, int slot) {
  const RabJob& job = *static_cast<const RabJob*>(ctx);
  Media::RabScratch& sc = job.media->rab_scratch[slot];
  const int n = static_cast<int>(job.media->rab_partners.size());
  // Interleaved devices: low indices have more partners b > a, so contiguous ranges would
  // not balance. Which slot routes a device does not change its list.
  for (int a = slot; a < n; a += job.slots) RabPartners(*job.model, job.media, a, sc);
}

void UpdateLeds(const Model& model, const PhysicsWorld& physics, const std::vector<RobotState>& robots, Media* m) {
  m->leds.clear();
  if (!m->any_camera) return;  // nobody looks: skip the index entirely
  const int n = static_cast<int>(robots.size());
  for (int i = 0; i < n; ++i) {
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
  for (size_t k = 0; k < model.lights.size(); ++k) {
    if (m->light_medium[k] < 0 || LedOff(model.lights[k].color)) continue;
    LitLed l;
    l.pos = model.lights[k].position;
    l.color = model.lights[k].color;
    l.medium = m->light_medium[k];
    m->leds.push_back(l);
  }
  m->led_grid.Build(static_cast<int>(m->leds.size()), [&](int k) { return Vec2(m->leds[k].pos.head<2>()); });
  m->camera_body_grid.Build(n, [&](int i) { return m->body_xy[i]; });
  if (!m->obstacle_xy.empty())
    m->camera_obstacle_grid.BuildDiscs(static_cast<int>(m->obstacle_xy.size()), [&](int k) { return m->obstacle_xy[k]; },
                                       [&](int k) { return m->obstacle_radius[k]; });
}
}  // namespace

/// A grid of the obstacles, each in every cell its bounding disc, widened by `slack_cells`
/// cells, overlaps (a box's margins need half a cell: BuildBoxes).
static void SetupObstacleGrid(const Vec2& lo, const Vec2& hi, double cell, double slack_cells, const Media& m,
                              PointGrid* g) {
  const size_t n_obs = m.obstacle_radius.size();
  g->Setup(lo, hi, cell, 0, 4 * n_obs + 64);
  size_t entries = 0;
  for (double r : m.obstacle_radius) entries += g->DiscEntries(r + slack_cells * g->cell);
  g->items.assign(entries, 0);
}

void InitMedia(const Model& model, Media* m) {
  const size_t n = model.robots.size();
  m->rab_inbox.resize(n);
  m->body_xy.assign(n, Vec2::Zero());
  m->rab_medium.assign(n, -1);
  m->rab_member.assign(n, 0);
  m->rab_pos.assign(n, Vec3::Zero());
  m->rab_yaw.assign(n, 0);
  m->rab_partners.resize(n);
  m->rab_scratch.clear();  // sized by UpdateMedia for its runner's slots
  m->led_medium.assign(n, -1);
  m->camera_medium.assign(n, -1);
  m->rab_max_range = 0;
  m->any_camera = false;
  m->camera_half_range = 0;
  size_t rab_count = 0, led_capacity = 0;
  for (size_t i = 0; i < n; ++i) {
    const RobotDef& def = model.robots[i];
    const ControllerDef& c = model.controllers[def.controller];
    // Only the sensor puts a robot in the RAB medium (spec §5.1 QUIRK, docs/compatibility.md).
    if (const DeviceConfig* d = c.Find(DeviceType::RabSensor)) {
      m->rab_medium[i] = MediumIndex(model.rab_media, d->Attr("medium"));
      if (m->rab_medium[i] >= 0) {
        ++rab_count;
        m->rab_max_range = std::max(m->rab_max_range, def.rab_range);
        if (m->rab_inbox[i].capacity() < 16) m->rab_inbox[i].reserve(std::min<size_t>(n, 64));
        if (m->rab_partners[i].capacity() < 16) m->rab_partners[i].reserve(std::min<size_t>(n, 64));
      }
    }
    if (const DeviceConfig* d = c.Find(DeviceType::LedsActuator)) {
      m->led_medium[i] = MediumIndex(model.led_media, d->Attr("medium"));
      if (m->led_medium[i] >= 0) led_capacity += footbot::kLedCount;
    }
    if (const DeviceConfig* d = c.Find(DeviceType::CameraSensor)) {
      m->camera_medium[i] = MediumIndex(model.led_media, d->Attr("medium"));
      if (m->camera_medium[i] >= 0) {
        m->any_camera = true;
        m->camera_half_range = std::max(m->camera_half_range, footbot::kCameraElevation * std::tan(def.camera_aperture));
      }
    }
  }
  const size_t n_obs = model.obstacles.size();
  m->obstacle_xy.assign(n_obs, Vec2::Zero());
  m->obstacle_cs.assign(n_obs, Vec2(1, 0));
  m->obstacle_radius.assign(n_obs, 0);
  m->obstacle_lo.assign(n_obs, Vec2::Zero());
  m->obstacle_hi.assign(n_obs, Vec2::Zero());
  m->obstacle_top.assign(n_obs, 0);
  m->obstacle_led_medium.assign(n_obs, -1);
  m->obstacle_max_radius = 0;
  for (size_t o = 0; o < n_obs; ++o) {
    const ObstacleDef& def = model.obstacles[o];
    m->obstacle_top[o] = def.z + def.height;
    const double r = (def.kind == ShapeKind::Cylinder ? def.radius : 0.5 * std::hypot(def.size_x, def.size_y)) + 1e-6;
    m->obstacle_radius[o] = r;
    m->obstacle_max_radius = std::max(m->obstacle_max_radius, r);
    if (!def.leds.empty()) {
      m->obstacle_led_medium[o] = MediumIndex(model.led_media, def.led_medium);
      led_capacity += def.leds.size();
    }
  }
  m->light_medium.assign(model.lights.size(), -1);
  for (size_t k = 0; k < model.lights.size(); ++k) m->light_medium[k] = MediumIndex(model.led_media, model.lights[k].medium);
  led_capacity += model.lights.size();

  // Grids over the arena (points outside fall into the border cells), cells about the
  // reach of a query so that it touches at most 3x3 cells; cell counts stay O(points).
  const Vec2 lo = model.arena.Min(), hi = model.arena.Max();
  if (rab_count >= 2) {
    const double near = m->rab_max_range + footbot::kRadius;
    m->rab_grid.Setup(lo, hi, near, n, 4 * n + 64);
    SetupObstacleGrid(lo, hi, near / 4, 0.5, *m, &m->rab_obstacle_grid);
  }
  m->leds.clear();
  m->leds.reserve(led_capacity);
  if (m->any_camera) {
    double h = m->camera_half_range;
    if (!(h > 0) || !std::isfinite(h)) h = 1e9;  // aperture >= 90°: the whole arena
    m->led_grid.Setup(lo, hi, h, led_capacity, 4 * led_capacity + 64);
    // Occlusion rays are at most h·sqrt(2) long: cells of about h/2 keep the cells a ray's
    // box touches few and small.
    m->camera_body_grid.Setup(lo, hi, h / 2, n, 4 * n + 64);
    SetupObstacleGrid(lo, hi, h / 2, 0, *m, &m->camera_obstacle_grid);
  }
  m->rab_devices = static_cast<int>(rab_count);
  m->ready = true;
}

void UpdateMedia(const Model& model, const PhysicsWorld& physics, const std::vector<RobotState>& robots, Media* m,
                 const SlotRunner& runner) {
  if (!m->ready) InitMedia(model, m);
  const int n = static_cast<int>(robots.size());
  const bool rab = m->rab_devices >= 2;
  if (rab || m->any_camera) {
    for (int i = 0; i < n; ++i) {
      const Pose2 p = physics.RobotPose(i);
      m->body_xy[i] = Vec2(p.x, p.y);
      m->rab_pos[i] = Vec3(p.x, p.y, model.robots[i].z + footbot::kRabElevation);
      m->rab_yaw[i] = p.yaw;
    }
    for (size_t k = 0; k < m->obstacle_xy.size(); ++k) {
      const Pose2 p = physics.ObstaclePose(static_cast<int>(k));
      m->obstacle_xy[k] = Vec2(p.x, p.y);
      m->obstacle_cs[k] = Vec2(std::cos(p.yaw), std::sin(p.yaw));
      const ObstacleDef& o = model.obstacles[k];
      const Vec2& cs = m->obstacle_cs[k];
      const Vec2 half = o.kind == ShapeKind::Cylinder
                            ? Vec2(o.radius, o.radius)
                            : Vec2(std::abs(cs.x()) * o.size_x / 2 + std::abs(cs.y()) * o.size_y / 2,
                                   std::abs(cs.y()) * o.size_x / 2 + std::abs(cs.x()) * o.size_y / 2);
      // Rounding in BoxEntry/CircleEntry is ~1e-16 of the coordinates: 1e-9 is ample.
      const Vec2 margin = (half + m->obstacle_xy[k].cwiseAbs()) * 1e-9 + Vec2(1e-9, 1e-9);
      m->obstacle_lo[k] = m->obstacle_xy[k] - half - margin;
      m->obstacle_hi[k] = m->obstacle_xy[k] + half + margin;
    }
  }
  if (rab && RabBegin(robots, m)) {
    // A few devices are not worth waking the threads for (the result is the same).
    const int slots = runner.run && m->rab_devices >= 64 ? std::max(1, runner.slots) : 1;
    if (static_cast<int>(m->rab_scratch.size()) < slots) {  // first tick: allocates once
      m->rab_scratch.resize(slots);
      for (Media::RabScratch& sc : m->rab_scratch) SizeRabScratch(model, &sc);
    }
    RabJob job{&model, m, slots};
    if (slots > 1) runner.run(runner.pool, RabSlot, &job);
    else RabSlot(&job, 0);
    RabDeliver(m);
  }
  UpdateLeds(model, physics, robots, m);
}

}  // namespace essaim
