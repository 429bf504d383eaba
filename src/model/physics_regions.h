// Which physics engine owns a point: the regions of several <dynamics2d> engines (ARGoS's
// <boundaries>), or the strips of one engine's regions="K". Shared by the loader (every
// entity must fall in some engine) and the physics (robots migrate as they move).
#pragma once
#include <string>
#include <vector>

#include "core/math.h"
#include "model/model.h"

namespace essaim {

/// Twice the signed area of a polygon (m²): positive when its vertices run counter-clockwise.
double TwiceSignedArea(const std::vector<Vec2>& polygon);

/// Whether `p` lies inside the polygon. Half-open (a crossing test along +x): a point on an
/// edge two polygons share is inside exactly one of them.
bool PolygonContains(const std::vector<Vec2>& polygon, const Vec2& p);

/// The first region, in declaration order, that contains `p` (an unbounded one contains
/// everything); `fallback` if none does (a body pushed out of every region stays where it is).
int RegionOf(const std::vector<PhysicsRegionDef>& regions, const Vec2& p, int fallback);

/// What is wrong with a region's boundaries ("" if nothing): under three vertices, not
/// counter-clockwise, crossing edges, bottom not below top.
std::string RegionProblem(const PhysicsRegionDef& region);

/// `count` strips of equal width across the arena's longer side, the outer ones reaching out
/// to the coordinate limit so that every position is in one. Ids "<id>_0", "<id>_1", ...
std::vector<PhysicsRegionDef> ArenaStrips(const ArenaDef& arena, const std::string& id, int count);

}  // namespace essaim
