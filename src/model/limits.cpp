#include "model/limits.h"

#include <algorithm>
#include <cmath>

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

std::string EntityCountProblem(size_t count, const LimitsDef& limits) {
  if (static_cast<double>(count) <= static_cast<double>(limits.entities)) return "";
  return std::to_string(count) + " entities are over the limit of " + std::to_string(limits.entities) +
         " per experiment (<system max_entities>)";
}

}  // namespace essaim
