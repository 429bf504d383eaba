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

/// What an experiment asks for (doubles: a file may ask for 1e18).
struct EntityCounts {
  double robots = 0;
  double objects = 0;  // boxes, cylinders, lights
};

/// What one entity is taken to cost, from the peaks measured at scale (docs/scale.md: 46-59
/// KB a foot-bot, its Lua state included) with a margin.
constexpr double kBytesPerRobot = 64 * 1024;
constexpr double kBytesPerObject = 4 * 1024;

/// "" when the experiment fits: with <system max_entities>, at most that many entities;
/// without it, an estimate within half of the memory this process may use. Else why not.
std::string EntityCountProblem(EntityCounts counts, const LimitsDef& limits);

/// Positions further than this from the origin on an axis are refused: Box2D holds them as
/// floats and asserts they are finite.
constexpr double kMaxCoordinate = 1e6;

}  // namespace essaim
