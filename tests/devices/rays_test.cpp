// Whole experiments driven by the ray sensors (issue "Every foot-bot sensor and
// actuator"): proximity-based obstacle avoidance spreads 30 robots over a walled arena
// with obstacles without any ending inside an obstacle or outside the walls; phototaxis
// with the light sensor brings every robot to the light. Assertions on final poses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "model/xml_loader.h"
#include "sim/step.h"
#include "sim/world.h"

namespace essaim {
namespace {

struct Finished {
  std::unique_ptr<Model> model;
  std::unique_ptr<World> world;
};

Finished RunFile(const std::string& name) {
  Finished r;
  ErrorList errors;
  LoadOptions lo;
  r.model = LoadExperimentFile(std::string(ESSAIM_SOURCE_DIR "/tests/devices/") + name, lo, &errors);
  EXPECT_TRUE(r.model) << errors.Format();
  if (!r.model) return r;
  std::string error;
  SimOptions so;
  so.strict = true;
  r.world = World::Create(*r.model, so, &error);
  EXPECT_TRUE(r.world) << error;
  if (!r.world) return r;
  while (Step(*r.world) == StepStatus::Running) {
  }
  EXPECT_TRUE(r.world->failure.empty()) << r.world->failure;
  EXPECT_TRUE(r.world->controller_errors.empty()) << r.world->controller_errors[0].message;
  return r;
}

/// Signed distance from point p to an obstacle's footprint (negative inside), m.
double DistanceToObstacle(const ObstacleDef& o, const Pose2& pose, const Vec2& p) {
  const Vec2 d = p - Vec2(pose.x, pose.y);
  if (o.kind == ShapeKind::Cylinder) return d.norm() - o.radius;
  // Into the box frame.
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  const Vec2 local(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
  const Vec2 q(std::fabs(local.x()) - o.size_x / 2, std::fabs(local.y()) - o.size_y / 2);
  const double outside = Vec2(std::max(q.x(), 0.0), std::max(q.y(), 0.0)).norm();
  return outside + std::min(std::max(q.x(), q.y()), 0.0);
}

TEST(RaysIntegration, ObstacleAvoidanceSpreadsThirtyRobotsAndNoneEndsInsideAnything) {
  Finished r = RunFile("rays_avoidance.argos");
  ASSERT_TRUE(r.world);
  const Model& m = *r.model;
  const World& w = *r.world;
  ASSERT_EQ(m.robots.size(), 30u);
  ASSERT_EQ(w.tick, 2500u);
  const double inner = 2.45;  // inner faces of the walls
  int left_start = 0;
  int quadrant[4] = {0, 0, 0, 0};
  double closest = 1e9;
  for (int i = 0; i < 30; ++i) {
    const Pose2 p = w.physics.RobotPose(i);
    const Vec2 c(p.x, p.y);
    // Inside the walls: the body may press at most a couple of cm into a wall.
    EXPECT_LT(std::fabs(p.x), inner - footbot::kRadius + 0.02) << m.robots[i].id;
    EXPECT_LT(std::fabs(p.y), inner - footbot::kRadius + 0.02) << m.robots[i].id;
    for (size_t o = 0; o < m.obstacles.size(); ++o) {
      const double d = DistanceToObstacle(m.obstacles[o], w.physics.ObstaclePose(static_cast<int>(o)), c);
      closest = std::min(closest, d);
      EXPECT_GT(d, footbot::kRadius - 0.02) << m.robots[i].id << " in " << m.obstacles[o].id;
    }
    // Started in [-2.3, -0.3]²: count those that left that square, and the quadrants.
    const bool in_start = p.x > -2.3 - 0.1 && p.x < -0.3 + 0.1 && p.y > -2.3 - 0.1 && p.y < -0.3 + 0.1;
    left_start += !in_start;
    quadrant[(p.x > 0 ? 1 : 0) + (p.y > 0 ? 2 : 0)]++;
  }
  EXPECT_GE(left_start, 15) << "the swarm should spread out of its start corner";
  for (int q = 0; q < 4; ++q) EXPECT_GE(quadrant[q], 2) << "quadrant " << q;
  // Sanity: the robots did reach the obstacles' neighbourhood at the end of the run.
  EXPECT_LT(closest, 1.0);
}

TEST(RaysIntegration, PhototaxisReachesTheLight) {
  Finished r = RunFile("rays_phototaxis.argos");
  ASSERT_TRUE(r.world);
  const Model& m = *r.model;
  ASSERT_EQ(m.lights.size(), 1u);
  const Vec2 light(m.lights[0].position.x(), m.lights[0].position.y());
  for (size_t i = 0; i < m.robots.size(); ++i) {
    const Pose2 start = m.robots[i].pose;
    const Pose2 p = r.world->physics.RobotPose(static_cast<int>(i));
    EXPECT_GT((Vec2(start.x, start.y) - light).norm(), 4.5) << m.robots[i].id;
    EXPECT_LT((Vec2(p.x, p.y) - light).norm(), 1.0) << m.robots[i].id;
  }
}

}  // namespace
}  // namespace essaim
