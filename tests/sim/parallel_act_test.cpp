// The act stage runs on the pool for large swarms (sim/step.cpp: from a few hundred robots):
// noisy wheels draw from each robot's actuator stream and set its own servo; the result must
// not depend on the thread count.
#include <gtest/gtest.h>

#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

std::string Crowd(int robots) {
  const std::string arena =
      "<distribute><position method=\"uniform\" min=\"-4.8,-4.8,0\" max=\"4.8,4.8,0\"/>"
      "<orientation method=\"uniform\" min=\"0,0,0\" max=\"360,0,0\"/>"
      "<entity quantity=\"" +
      std::to_string(robots) +
      "\" max_trials=\"100\"><foot-bot id=\"fb\"><controller config=\"c\"/></foot-bot></entity></distribute>";
  const std::string controller =
      "<lua_controller id=\"c\"><actuators><differential_steering implementation=\"default\" "
      "bias_stddev=\"0.01\" factor_stddev=\"0.2\"/></actuators>"
      "<sensors><positioning implementation=\"default\"/></sensors><params script=\"wander.lua\"/></lua_controller>";
  return Experiment(arena, controller, 30, 21);
}

uint64_t RunHash(int threads, uint64_t* start_hash) {
  TempDir d;
  d.Write("wander.lua", WanderController("0.2", "8", "12"));
  LoadOptions lo;
  lo.threads = threads;
  Scene s = Load(d, Crowd(400), lo);
  EXPECT_TRUE(s.ok()) << s.error;
  if (!s.ok()) return 0;
  *start_hash = PoseHash(*s.world);
  while (Step(*s.world) == StepStatus::Running) {
  }
  EXPECT_EQ(s.world->tick, 30u);
  return PoseHash(*s.world);
}

TEST(ParallelAct, NoisyWheelsGiveTheSameSwarmAtAnyThreadCount) {
  uint64_t start = 0;
  const uint64_t one = RunHash(1, &start);
  EXPECT_NE(one, start);  // the swarm moved
  EXPECT_EQ(one, RunHash(2, &start));
  EXPECT_EQ(one, RunHash(4, &start));
}

}  // namespace
}  // namespace essaim
