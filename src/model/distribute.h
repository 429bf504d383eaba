// <distribute> generators and the overlap test used to place entities, as ARGoS's <distribute>.
#pragma once
#include "core/math.h"
#include "core/rng.h"
#include "model/model.h"

namespace essaim {

struct Generator {
  enum class Kind { Uniform, Gaussian, Constant, Grid } kind = Kind::Constant;
  Vec3 a = Vec3::Zero();      // uniform: min; gaussian: mean; constant: values; grid: center
  Vec3 b = Vec3::Zero();      // uniform: max; gaussian: std_dev; grid: distances
  int layout[3] = {1, 1, 1};  // grid only
  /// Value for the k-th draw (k counts every attempt, as ARGoS's grid does). Returns false
  /// when a grid has no cell k.
  bool Next(Rng& rng, int k, Vec3* out) const;
};

/// Rounds to 6 significant digits, as ARGoS writes generated values into the XML.
double RoundSignificant6(double v);

/// A footprint on the floor: a circle or a rotated rectangle.
struct Footprint {
  bool is_circle = true;
  Vec2 center = Vec2::Zero();
  double radius = 0;                       // circle
  double half_x = 0, half_y = 0, yaw = 0;  // rectangle
};

/// An obstacle's footprint at its pose.
Footprint ObstacleFootprint(const ObstacleDef& o);

/// True when the two footprints overlap with positive depth (touching is not a collision,
/// as in ARGoS's placement check).
bool FootprintsOverlap(const Footprint& a, const Footprint& b);

}  // namespace essaim
