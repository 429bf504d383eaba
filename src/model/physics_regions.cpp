#include "model/physics_regions.h"

#include "model/limits.h"

namespace essaim {

double TwiceSignedArea(const std::vector<Vec2>& polygon) {
  double a = 0;
  const size_t n = polygon.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec2& p = polygon[i];
    const Vec2& q = polygon[(i + 1) % n];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return a;
}

bool PolygonContains(const std::vector<Vec2>& polygon, const Vec2& p) {
  bool inside = false;
  const size_t n = polygon.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[j];
    if ((a.y() > p.y()) == (b.y() > p.y())) continue;
    const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
    if (p.x() < x) inside = !inside;
  }
  return inside;
}

int RegionOf(const std::vector<PhysicsRegionDef>& regions, const Vec2& p, int fallback) {
  for (size_t r = 0; r < regions.size(); ++r)
    if (!regions[r].Bounded() || PolygonContains(regions[r].sides, p)) return static_cast<int>(r);
  return fallback;
}

namespace {
double Cross(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

/// Whether segments ab and cd cross at a point inside both (touching ends do not count).
bool ProperlyCross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double d1 = Cross(a, b, c), d2 = Cross(a, b, d), d3 = Cross(c, d, a), d4 = Cross(c, d, b);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}
}  // namespace

std::string RegionProblem(const PhysicsRegionDef& region) {
  if (!region.Bounded()) return "";
  const std::vector<Vec2>& s = region.sides;
  const size_t n = s.size();
  if (n < 3) return "<sides> needs at least 3 vertices, found " + std::to_string(n);
  for (const Vec2& v : s)
    if (!std::isfinite(v.x()) || !std::isfinite(v.y()) || v.cwiseAbs().maxCoeff() > kMaxCoordinate)
      return "a vertex lies beyond 1e6 m from the origin";
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours through the closing edge
      if (ProperlyCross(s[i], s[(i + 1) % n], s[j], s[(j + 1) % n]))
        return "the edges of <sides> cross (vertices " + std::to_string(i + 1) + " and " + std::to_string(j + 1) +
               " start them)";
    }
  if (TwiceSignedArea(s) <= 0) return "the vertices of <sides> must run counter-clockwise (seen from above)";
  if (!(region.bottom < region.top)) return "<bottom height> must be below <top height>";
  return "";
}

std::vector<PhysicsRegionDef> ArenaStrips(const ArenaDef& arena, const std::string& id, int count) {
  std::vector<PhysicsRegionDef> strips;
  const bool along_x = arena.size.x() >= arena.size.y();
  const double lo = along_x ? arena.Min().x() : arena.Min().y();
  const double width = (along_x ? arena.size.x() : arena.size.y()) / count;
  const double far = kMaxCoordinate;
  for (int k = 0; k < count; ++k) {
    const double a = k == 0 ? -far : lo + k * width;
    const double b = k == count - 1 ? far : lo + (k + 1) * width;
    PhysicsRegionDef r;
    r.id = id + "_" + std::to_string(k);
    r.bottom = -far;
    r.top = far;
    if (along_x)
      r.sides = {Vec2(a, -far), Vec2(b, -far), Vec2(b, far), Vec2(a, far)};
    else
      r.sides = {Vec2(-far, a), Vec2(far, a), Vec2(far, b), Vec2(-far, b)};
    strips.push_back(r);
  }
  return strips;
}

}  // namespace essaim
