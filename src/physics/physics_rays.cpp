// PhysicsWorld's rays and neighbour queries: Box2D's ray casts, the ray grid of bounding
// circles, the candidates gathered once per robot and height, and robots near a point.
#include <box2d/box2d.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>

#include "physics/physics_world.h"
#include "physics/physics_world_impl.h"

namespace essaim {

namespace {
/// m: the ray grid's cells, a side of about three foot-bot diameters. A scanner's disc
/// (1.51 m) spans 7 × 7 cells, the proximity ring's (0.19 m) one to four; smaller cells
/// file each robot in more of them, larger ones let more far shapes through.
constexpr double kRayCellSize = 0.5;
}  // namespace

namespace {
/// A shape's vertical extent (m): a robot's is the foot-bot's body, an obstacle's its own.
void HeightSpan(BodyKind kind, int index, const std::vector<double>& tops, const std::vector<double>& bottoms,
                double* bottom, double* top) {
  if (kind == BodyKind::Robot || kind == BodyKind::Gripper) {
    *bottom = 0;
    *top = footbot::kHeight;
  } else {
    *bottom = bottoms[index];
    *top = tops[index];
  }
}

/// Whether a query at height z can touch this shape: any robot but the excluded one, any
/// obstacle, whose vertical extent contains z.
bool ReachesHeight(BodyKind kind, int index, double z, int exclude_robot, const std::vector<double>& tops,
                   const std::vector<double>& bottoms) {
  if (kind == BodyKind::None || (kind != BodyKind::Obstacle && index == exclude_robot)) return false;
  double bottom, top;
  HeightSpan(kind, index, tops, bottoms, &bottom, &top);
  return z >= bottom && z <= top;
}

class ClosestRay : public b2RayCastCallback {
 public:
  ClosestRay(const std::vector<double>& tops, const std::vector<double>& bottoms, double z, int exclude)
      : tops_(tops), bottoms_(bottoms), z_(z), exclude_(exclude) {}
  float ReportFixture(b2Fixture* f, const b2Vec2& point, const b2Vec2&, float fraction) override {
    uintptr_t tag = f->GetUserData().pointer;
    BodyKind kind = TagKind(tag);
    int index = TagIndex(tag);
    if (!ReachesHeight(kind, index, z_, exclude_, tops_, bottoms_)) return -1;
    if (fraction > fraction_) return -1;  // a farther hit in a later region's world
    hit.kind = kind;
    hit.index = index;
    hit.point = {point.x, point.y};
    fraction_ = fraction;
    return fraction;  // clip: keep looking for closer hits only
  }
  RayHit hit;
  float fraction_ = 1;

 private:
  const std::vector<double>& tops_;
  const std::vector<double>& bottoms_;
  double z_;
  int exclude_;
};

class RobotQuery : public b2QueryCallback {
 public:
  RobotQuery(const Vec2& c, double r, std::vector<int>* out) : c_(c), r2_(r * r), out_(out) {}
  bool ReportFixture(b2Fixture* f) override {
    uintptr_t tag = f->GetUserData().pointer;
    if (TagKind(tag) != BodyKind::Robot) return true;
    b2Vec2 p = f->GetBody()->GetPosition();
    if ((Vec2(p.x, p.y) - c_).squaredNorm() <= r2_) out_->push_back(TagIndex(tag));
    return true;
  }

 private:
  Vec2 c_;
  double r2_;
  std::vector<int>* out_;
};

/// The gripper discs the segment p1→p2 crosses, reported to `cb` as Box2D's tree walk reports
/// a fixture (the discs are out of the tree: physics_grip.cpp). Found in the ray grid, piece
/// by piece of about a cell along the segment: a disc the segment crosses has its filed box
/// meet that piece's box.
void CastAtDiscs(const PhysicsWorld::Impl& im, const b2Vec2& p1, const b2Vec2& p2, ClosestRay* cb) {
  b2RayCastInput in;
  in.p1 = p1;
  in.p2 = p2;
  in.maxFraction = 1;
  const double dx = static_cast<double>(p2.x) - p1.x, dy = static_cast<double>(p2.y) - p1.y;
  const int pieces = std::max(1, static_cast<int>(std::ceil(std::hypot(dx, dy) / im.ray_grid.CellSize())));
  for (int k = 0; k < pieces; ++k) {
    const double t0 = static_cast<double>(k) / pieces, t1 = static_cast<double>(k + 1) / pieces;
    const double x0 = p1.x + dx * t0, y0 = p1.y + dy * t0, x1 = p1.x + dx * t1, y1 = p1.y + dy * t1;
    im.ray_grid.ForEachOnceInBox(std::min(x0, x1), std::min(y0, y1), std::max(x0, x1), std::max(y0, y1), [&](int i) {
      auto* f = const_cast<b2Fixture*>(im.ray_circles[i].fixture);
      b2RayCastOutput out;
      if (TagKind(f->GetUserData().pointer) != BodyKind::Gripper || !f->RayCast(&out, in, 0)) return;
      cb->ReportFixture(f, (1.0f - out.fraction) * p1 + out.fraction * p2, out.normal, out.fraction);
    });
  }
}
}  // namespace

RayHit PhysicsWorld::CastRay(const Vec2& from, const Vec2& to, double z, int exclude_robot) const {
  ClosestRay cb(impl_->obstacle_top, impl_->obstacle_bottom, z, exclude_robot);
  b2Vec2 p1(static_cast<float>(from.x()), static_cast<float>(from.y()));
  b2Vec2 p2(static_cast<float>(to.x()), static_cast<float>(to.y()));
  if (b2DistanceSquared(p1, p2) <= 0) return {};
  for (Impl::Region& region : impl_->regions) region.world->RayCast(&cb, p1, p2);
  EnsureRayGrid();
  CastAtDiscs(*impl_, p1, p2, &cb);
  if (cb.hit.Hit()) cb.hit.distance = (to - from).norm() * cb.fraction_;
  return cb.hit;
}

namespace {
/// A circle round the shape where b2Fixture::RayCast sees it (the body's current transform):
/// a circle is its own; a polygon's is centred on its centroid through its farthest vertex
/// (2.4.1's polygon ray cast ignores the skin radius). Tight, so CastRay's nearest-first
/// scan stops early: the box round a foot-bot would be 41% wider than the foot-bot.
void BoundingCircle(const b2Fixture& f, double* cx, double* cy, double* r) {
  const b2Transform& xf = f.GetBody()->GetTransform();
  const b2Shape* shape = f.GetShape();
  if (shape->GetType() == b2Shape::e_circle) {
    const auto* circle = static_cast<const b2CircleShape*>(shape);
    const b2Vec2 c = b2Mul(xf, circle->m_p);
    *cx = c.x;
    *cy = c.y;
    *r = circle->m_radius;
    return;
  }
  const auto* poly = static_cast<const b2PolygonShape*>(shape);
  double r2 = 0;
  for (int i = 0; i < poly->m_count; ++i) {
    const double dx = static_cast<double>(poly->m_vertices[i].x) - poly->m_centroid.x;
    const double dy = static_cast<double>(poly->m_vertices[i].y) - poly->m_centroid.y;
    r2 = std::max(r2, dx * dx + dy * dy);
  }
  const b2Vec2 c = b2Mul(xf, poly->m_centroid);
  *cx = c.x;
  *cy = c.y;
  *r = std::sqrt(r2);
}

// m: far above float rounding at arena scale (Box2D's hit points lie within ~1e-5 m of the
// shape), so no shape a ray touches is ever dropped, nor cut off by CastRay's early stop.
constexpr double kCircleSlack = 1e-3;
}  // namespace

namespace {
/// The bounding circle of every shape (non-finite ones dropped: no ray can hit them
/// either), filed in the ray grid by their boxes.
template <class Impl>
void FileRayCircle(Impl* im, b2Fixture* f) {
  const uintptr_t tag = f->GetUserData().pointer;
  const BodyKind kind = TagKind(tag);
  if (kind == BodyKind::None) return;
  ShapeCircle c;
  BoundingCircle(*f, &c.cx, &c.cy, &c.r);
  c.r += kCircleSlack;
  if (!std::isfinite(c.cx) || !std::isfinite(c.cy) || !std::isfinite(c.r)) return;
  const int index = TagIndex(tag);
  if (kind != BodyKind::Obstacle) c.robot = index;  // a robot's body or gripper disc
  HeightSpan(kind, index, im->obstacle_top, im->obstacle_bottom, &c.bottom, &c.top);
  c.fixture = f;
  im->ray_circles.push_back(c);
}

/// Every shape in the worlds' body lists' order, each robot's gripper disc (kept apart, in
/// Impl::disc_shelf) just before its body, where the disc's body stood in that list when
/// it was made with its robot.
template <class Impl>
void GatherRayCircles(Impl* im) {
  im->ray_circles.clear();
  for (auto& region : im->regions)
    for (b2Body* b = region.world->GetBodyList(); b; b = b->GetNext())
      for (b2Fixture* f = b->GetFixtureList(); f; f = f->GetNext()) {
        if (TagKind(f->GetUserData().pointer) == BodyKind::Robot)
          FileRayCircle(im, im->discs[TagIndex(f->GetUserData().pointer)]->GetFixtureList());
        FileRayCircle(im, f);
      }
}

template <class Impl>
void FileRayCircles(Impl* im) {
  GatherRayCircles(im);
  std::vector<ShapeCircle>& circles = im->ray_circles;
  const int n = static_cast<int>(circles.size());
  Vec2 lo = Vec2::Zero(), hi = Vec2::Zero();
  if (n > 0) lo = hi = Vec2(circles[0].cx, circles[0].cy);
  for (const ShapeCircle& c : circles) {
    lo = lo.cwiseMin(Vec2(c.cx - c.r, c.cy - c.r));
    hi = hi.cwiseMax(Vec2(c.cx + c.r, c.cy + c.r));
  }
  // A robot flung far away must not make the grid huge: past a few cells per shape, the
  // cells grow instead (queries get slower, never wrong). Room for a foot-bot-sized circle
  // in four cells each.
  im->ray_grid.CoverSpan(lo, hi, kRayCellSize, std::max(4096.0, 4.0 * n));
  im->ray_grid.Reserve(4 * circles.size(), circles.size());
  im->ray_grid.FileBoxes(
      n, [&](int i) { return Vec2(circles[i].cx - circles[i].r, circles[i].cy - circles[i].r); },
      [&](int i) { return Vec2(circles[i].cx + circles[i].r, circles[i].cy + circles[i].r); });
}
}  // namespace

void PhysicsWorld::EnsureRayGrid() const {
  Impl& im = *impl_;
  if (im.grid_built_at.load(std::memory_order_acquire) == im.shapes_moved) return;
  // The first query after a change rebuilds; the others of a parallel stage wait for it.
  std::lock_guard<std::mutex> lock(im.grid_mutex);
  if (im.grid_built_at.load(std::memory_order_relaxed) == im.shapes_moved) return;
  FileRayCircles(&im);
  im.grid_built_at.store(im.shapes_moved, std::memory_order_release);
}

namespace {
/// The gathers' scan: circles filed in the grid cells over the box (x0, y0)-(x1, y1) that span
/// `z` (ReachesHeight's rule), are not robot `exclude_robot`, reach the disc of radius `r` round
/// `center` and pass `keep(dx, dy, circle radius)` (offset from the centre). Each goes into
/// `found` with its `near`; [*lo, *hi] covers those.
template <class Keep>
void Collect(const UniformGrid& grid, const std::vector<ShapeCircle>& circles, double x0, double y0, double x1,
             double y1, const Vec2& center, double r, double z, int exclude_robot, Keep&& keep,
             std::vector<RayCandidate>* found, double* lo, double* hi) {
  grid.ForEachOnceInBox(x0, y0, x1, y1, [&](int i) {
    const ShapeCircle& g = circles[i];
    if (z < g.bottom || z > g.top || (exclude_robot >= 0 && g.robot == exclude_robot)) return;
    const double dx = g.cx - center.x(), dy = g.cy - center.y();
    const double d2 = dx * dx + dy * dy;
    if (d2 > (g.r + r) * (g.r + r) || !keep(dx, dy, g.r)) return;
    const double near = std::sqrt(d2) - g.r;
    *lo = std::min(*lo, near);
    *hi = std::max(*hi, near);
    found->push_back({near, g.cx, g.cy, g.r, g.fixture});
  });
}

/// Whether a circle at offset (dx, dy) from the apex, of radius r, comes within r of the wedge
/// from unit vector u0 counter-clockwise to u1 (less than π on): a point of the wedge lies left
/// of u0 and right of u1, so a circle holding one has its centre within r of both lines.
/// A superset of the circles that meet it.
bool NearWedge(double dx, double dy, double r, const Vec2& u0, const Vec2& u1) {
  return u0.x() * dy - u0.y() * dx >= -r && dx * u1.y() - dy * u1.x() >= -r;
}
}  // namespace

void PhysicsWorld::GatherRayCandidates(const Vec2& center, double radius, double z, int exclude_robot,
                                       RayCandidates* out) const {
  EnsureRayGrid();
  out->scratch.clear();
  const double r = radius + kCircleSlack;
  double lo = 0, hi = 0;  // m, range of `near`
  Collect(
      impl_->ray_grid, impl_->ray_circles, center.x() - r, center.y() - r, center.x() + r, center.y() + r, center, r, z,
      exclude_robot, [](double, double, double) { return true; }, &out->scratch, &lo, &hi);
  out->center = center;
  SortNearestFirst(lo, hi, out);
}

void PhysicsWorld::GatherWedgeCandidates(const Vec2& center, double radius, const Vec2& u0, const Vec2& u1, double z,
                                         int exclude_robot, RayCandidates* out) const {
  EnsureRayGrid();
  out->scratch.clear();
  const double r = radius + kCircleSlack;
  // The sector's bounding box: its apex, the ends of its edges, and its rim where it crosses
  // an axis. The grid files circles by their boxes, so those that meet the sector are in it.
  double x0 = center.x(), y0 = center.y(), x1 = x0, y1 = y0;
  auto cover = [&](const Vec2& u) {
    x0 = std::min(x0, center.x() + r * u.x());
    x1 = std::max(x1, center.x() + r * u.x());
    y0 = std::min(y0, center.y() + r * u.y());
    y1 = std::max(y1, center.y() + r * u.y());
  };
  cover(u0);
  cover(u1);
  for (const Vec2& axis : {Vec2(1, 0), Vec2(0, 1), Vec2(-1, 0), Vec2(0, -1)})
    if (NearWedge(axis.x(), axis.y(), 0, u0, u1)) cover(axis);
  double lo = 0, hi = 0;  // m, range of `near`
  Collect(
      impl_->ray_grid, impl_->ray_circles, x0 - kCircleSlack, y0 - kCircleSlack, x1 + kCircleSlack, y1 + kCircleSlack,
      center, r, z, exclude_robot, [&](double dx, double dy, double cr) { return NearWedge(dx, dy, cr, u0, u1); },
      &out->scratch, &lo, &hi);
  out->center = center;
  SortNearestFirst(lo, hi, out);
}

namespace {
/// m: CastRay's stop is tested against `near` rounded down by one to two of these steps, so a
/// ray tests at most the candidates of two more centimetres; std::sort was 40% of a gather.
constexpr double kNearStep = 0.01;
constexpr int kMaxNearSteps = 1024;
}  // namespace

void PhysicsWorld::SortNearestFirst(double lo, double hi, RayCandidates* out) {
  const std::vector<RayCandidate>& found = out->scratch;
  std::vector<RayCandidate>& items = out->items;
  items.resize(found.size());
  if (found.empty()) return;
  // Counting sort on `near` in steps; each is stored as the floor of the step below its own
  // (a lower bound even if (near - lo) / step rounded up, and non-decreasing along the
  // result). Same order for the same input: deterministic.
  double step = kNearStep;
  while ((hi - lo) / step > kMaxNearSteps) step *= 2;  // a huge obstacle: fewer, coarser steps
  const double inv_step = 1 / step;
  const int steps = static_cast<int>((hi - lo) * inv_step) + 1;
  std::vector<int>& ends = out->bucket_ends;
  ends.reserve(kMaxNearSteps + 2);  // once: later gathers never allocate for it
  auto step_of = [&](double near) { return std::min(static_cast<int>((near - lo) * inv_step), steps - 1); };
  const size_t n = found.size();
  if (n * n < 2 * static_cast<size_t>(steps)) {
    // Few candidates over many steps (a wedge's): a stable insertion sort on the step
    // (`ends` holds the steps placed so far) beats sweeping every step. Same order.
    ends.resize(n);
    for (size_t i = 0; i < n; ++i) {
      const int k = step_of(found[i].near);
      size_t j = i;
      for (; j > 0 && ends[j - 1] > k; --j) {
        ends[j] = ends[j - 1];
        items[j] = items[j - 1];
      }
      ends[j] = k;
      items[j] = found[i];
      items[j].near = lo + std::max(k - 1, 0) * step;
    }
    return;
  }
  ends.resize(steps + 1);
  BucketSort(
      static_cast<int>(n), &ends, [&](int i, auto&& file) { file(step_of(found[i].near)); },
      [&](int slot, int i) {
        items[slot] = found[i];
        items[slot].near = lo + std::max(step_of(found[i].near) - 1, 0) * step;
      });
}

RayHit PhysicsWorld::CastRay(const RayCandidates& candidates, const Vec2& from, const Vec2& to) const {
  // The same float input as CastRay gives b2World::RayCast.
  b2RayCastInput in;
  in.p1.Set(static_cast<float>(from.x()), static_cast<float>(from.y()));
  in.p2.Set(static_cast<float>(to.x()), static_cast<float>(to.y()));
  in.maxFraction = 1;
  if (candidates.items.empty() || b2DistanceSquared(in.p1, in.p2) <= 0) return {};
  const Vec2 d = to - from;
  const double len2 = d.squaredNorm();
  const double len = std::sqrt(len2);
  const double ux = d.x() / len, uy = d.y() / len;
  // Every point of candidate c is at least c.near from the gather centre, hence at least
  // c.near - start from the ray's start: once that exceeds the closest hit so far (or the
  // ray's length), no candidate left can be hit closer. The 1 mm the bounding circles are
  // inflated by keeps this safe against float rounding in Box2D's fractions.
  const double start = (from - candidates.center).norm();
  double reach = len;  // m, how far along the ray a better hit must lie
  float best = 2;
  const b2Fixture* closest = nullptr;
  for (const RayCandidate& c : candidates.items) {
    if (c.near - start > reach) break;
    // Rejects most candidates cheaply, in double: a circle the segment meets has its centre
    // within r of the ray's line, and between r before the start and r past the end.
    const double mx = c.cx - from.x(), my = c.cy - from.y();
    const double across = mx * uy - my * ux;
    if (across * across > c.r * c.r) continue;
    const double along = mx * ux + my * uy;
    if (along < -c.r || along > len + c.r) continue;
    // Box2D's own shape test. The tree's walk passes a clipped maxFraction instead of 1;
    // that only rejects hits no closer than the best so far, so the minimum is the same.
    const auto* f = static_cast<const b2Fixture*>(c.fixture);
    b2RayCastOutput out;
    if (!f->RayCast(&out, in, 0)) continue;
    if (out.fraction < best) {
      best = out.fraction;
      closest = f;
      reach = len * best;
    }
  }
  if (!closest) return {};
  RayHit hit;
  const uintptr_t tag = const_cast<b2Fixture*>(closest)->GetUserData().pointer;  // 2.4.1: no const getter
  hit.kind = TagKind(tag);
  hit.index = TagIndex(tag);
  hit.point = {(1.0f - best) * in.p1.x + best * in.p2.x, (1.0f - best) * in.p1.y + best * in.p2.y};
  hit.distance = (to - from).norm() * best;
  return hit;
}

void PhysicsWorld::RobotsNear(const Vec2& center, double radius, std::vector<int>* out) const {
  out->clear();
  RobotQuery q(center, radius, out);
  b2AABB box;
  box.lowerBound.Set(static_cast<float>(center.x() - radius), static_cast<float>(center.y() - radius));
  box.upperBound.Set(static_cast<float>(center.x() + radius), static_cast<float>(center.y() + radius));
  for (Impl::Region& region : impl_->regions) region.world->QueryAABB(&q, box);
  // The tree's order depends on insertion history, not on indices: sort for determinism.
  std::sort(out->begin(), out->end());
}

}  // namespace essaim
