// Range-and-bearing routing, the media stage's part that decides who hears whom. In phases:
// begin (members, grids), per device gather candidates and occluders, sort the occluders
// nearest first, test each pair for occlusion, then deliver the partners into inboxes.
#pragma once
#include <vector>

#include "devices/robot_state.h"
#include "model/model.h"

namespace essaim {

struct Media;
struct SlotRunner;

/// A robot whose body or gripper disc may hide a partner from one device: for each circle
/// the parts of CircleEntry that do not depend on the partner, computed once per device,
/// and a circle around both (Media::rab_bound_radius2) that a segment must meet to enter
/// either: one test rejects most robots off a pair's line for both circles.
struct RabOccluder {
  double bound2;              // m², |offset|² - R² of that circle around both
  double offset_x, offset_y;  // m, body centre minus device
  double tangent2;            // m², |offset|² - r²: the body's squared tangent length; +inf: cannot hide
  double disc_x, disc_y;      // m, gripper disc centre minus device
  double disc_tangent2;       // m², the same for the disc
  int body;                   // the robot
  int bucket;                 // of the smaller tangent2, see SortOccluders
};

/// One thread's working buffers for the devices it routes (sized once, reused).
struct RabScratch {
  std::vector<int> candidates;         // members after the device within reach, any order
  std::vector<RabOccluder> occluders;  // robots that may hide a partner: near tier, then far
  std::vector<RabOccluder> unsorted;   // occluders before bucketing
  std::vector<int> bucket_start;       // kOccluderBuckets + 1 offsets into occluders (near tier)
  // The far tier: robots beyond rab::kNearTier of the reach, made occluders (after the near
  // tier, bucketed alike) only when a pair needs them; most devices' pairs never do.
  std::vector<int> far;               // those robots, until then
  std::vector<int> far_bucket_start;  // kOccluderBuckets + 1 offsets into occluders
  bool far_ready = false;
  std::vector<int> sector_blocker;  // kProbeSectors occluders or -1, see FindBlockers
  std::vector<int> near_obstacles;  // within reach of one device, if few (kFewObstacles)
  bool walk_obstacles = false;      // too many near: each pair walks the obstacle grid
  std::vector<int> obstacle_stamp;  // dedup of near_obstacles
  int stamp = 0;
};

namespace rab {
/// Up to this many obstacles within reach, a device's pairs test them all; beyond, each
/// pair walks the obstacle grid's cells along its segment.
constexpr int kFewObstacles = 12;
constexpr int kOccluderBuckets = 64;
/// Blocker probes (rab_blockers.h): direction sectors (a power of 2), the reach of the
/// bodies that may block one, and how many robots within it make a crowd (fewer: no
/// probes, as most pairs are then unhidden and probing would not pay).
constexpr int kProbeSectors = 64;
constexpr double kBlockerReach = 1.0;  // m
constexpr int kCrowd = 8;
/// The near tier's radius as a fraction of the reach (at least kBlockerReach + 0.1 m): in
/// foraging's crowds of 100 and 300 (3 m range) half the devices or fewer need the far
/// tier (media instructions -5 % and -14 %; with 30 robots most do, +3 %).
constexpr double kNearTier = 0.5;
}  // namespace rab

/// Sizes the routing buffers for the model (InitMedia): grids and per-robot lists.
void InitRabRouting(const Model& model, Media* media);
/// Fills media->rab_inbox from this tick's positions (body_xy, rab_pos, obstacles): the
/// per-device work on the runner's slots, inboxes identical at any slot count.
void RouteRab(const Model& model, const RobotStates& robots, Media* media, const SlotRunner& runner);

}  // namespace essaim
