#include "model/limits.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/machine_memory.h"
#include "core/strings.h"

namespace essaim {

std::string ObstacleProblem(const ObstacleDef& o, const LimitsDef& limits) {
  const bool box = o.kind == ShapeKind::Box;
  const double side = box ? std::max({o.size_x, o.size_y, o.height}) : std::max(2 * o.radius, o.height);
  if (!(side <= limits.entity_size))
    return std::string(box ? "size " : "diameter or height ") + FormatDouble(side) + " m is over the limit of " +
           FormatDouble(limits.entity_size) + " m (<system max_entity_size>)";
  if (!(o.z >= 0)) return "z = " + FormatDouble(o.z) + " puts it below the floor (z must be >= 0)";
  if (!(std::abs(o.pose.x) <= kMaxCoordinate && std::abs(o.pose.y) <= kMaxCoordinate && o.z <= kMaxCoordinate))
    return "position beyond 1e6 m from the origin on an axis: Box2D cannot hold it";
  return "";
}

namespace {
std::string Count(double n) { return n >= 1e15 ? FormatDouble(n) : std::to_string(static_cast<long long>(n)); }

std::string GiB(double bytes) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f GiB", bytes / (1024.0 * 1024 * 1024));
  return b;
}
}  // namespace

std::string EntityCountProblem(EntityCounts counts, const LimitsDef& limits) {
  const double total = counts.robots + counts.objects;
  if (limits.entities > 0) {
    if (total <= static_cast<double>(limits.entities)) return "";
    return Count(total) + " entities are over the limit of " + std::to_string(limits.entities) +
           " per experiment (<system max_entities>)";
  }
  const double usable = static_cast<double>(UsableMemoryBytes());
  const double needed = counts.robots * kBytesPerRobot + counts.objects * kBytesPerObject;
  if (usable <= 0 || needed <= usable / 2) return "";
  return Count(total) + " entities (" + Count(counts.robots) + " foot-bots) would need about " + GiB(needed) +
         ", over half of the " + GiB(usable) +
         " this process may use (memory, ulimit -v, cgroup); <system max_entities=\"N\"/> allows N entities "
         "whatever the machine";
}

}  // namespace essaim
