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

/// A body or gripper disc that may hide a partner from one device: the parts of CircleEntry
/// that do not depend on the partner, computed once per device.
struct RabOccluder {
  double tangent2;            // m², |offset|² - r²: the squared tangent length from the device
  double offset_x, offset_y;  // m, circle centre minus device
  int body;                   // the robot it belongs to
  int bucket;                 // of tangent2, see SortOccluders
};

/// One thread's working buffers for the devices it routes (sized once, reused).
struct RabScratch {
  std::vector<int> candidates;         // members after the device within reach, any order
  std::vector<RabOccluder> occluders;  // those that may hide a partner, nearest bucket first
  std::vector<RabOccluder> unsorted;   // occluders before bucketing
  std::vector<int> bucket_start;       // kOccluderBuckets + 1 offsets into occluders
  std::vector<int> sector_blocker;     // kProbeSectors occluders or -1, see FindBlockers
  std::vector<int> near_obstacles;     // within reach of one device, if few (kFewObstacles)
  bool walk_obstacles = false;         // too many near: each pair walks the obstacle grid
  std::vector<int> obstacle_stamp;     // dedup of near_obstacles
  int stamp = 0;
};

namespace rab {
/// Up to this many obstacles within reach, a device's pairs test them all; beyond, each
/// pair walks the obstacle grid's cells along its segment.
constexpr int kFewObstacles = 12;
constexpr int kOccluderBuckets = 64;
/// Blocker probes (rab_blockers.h): direction sectors (a power of 2), the reach of the
/// bodies that may block one, and how many within it make a crowd (fewer: no probes, as
/// most pairs are then unhidden and probing would not pay).
constexpr int kProbeSectors = 64;
constexpr double kBlockerReach = 1.0;  // m
constexpr int kCrowd = 16;
}  // namespace rab

/// Sizes the routing buffers for the model (InitMedia): grids and per-robot lists.
void InitRabRouting(const Model& model, Media* media);
/// Fills media->rab_inbox from this tick's positions (body_xy, rab_pos, obstacles): the
/// per-device work on the runner's slots, inboxes identical at any slot count.
void RouteRab(const Model& model, const RobotStates& robots, Media* media, const SlotRunner& runner);

}  // namespace essaim
