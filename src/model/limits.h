// The size and count limits (LimitsDef) and the ranges an obstacle must fit, shared by the
// .argos loader and the loop functions' add_entity so that both refuse the same things.
#pragma once
#include <cstddef>
#include <string>

#include "model/model.h"

namespace essaim {

/// "" when `o` fits: sides within limits.entity_size, its base at or above the floor
/// (z >= 0), a position Box2D can hold. Else why not, e.g. "size 10000 m is over the limit
/// of 1000 m per side (<system max_entity_size>)".
std::string ObstacleProblem(const ObstacleDef& o, const LimitsDef& limits);

/// "" when an experiment of `count` entities fits limits.entities, else why not.
std::string EntityCountProblem(size_t count, const LimitsDef& limits);

/// Positions further than this from the origin on an axis are refused: Box2D holds them as
/// floats and asserts they are finite.
constexpr double kMaxCoordinate = 1e6;

}  // namespace essaim
