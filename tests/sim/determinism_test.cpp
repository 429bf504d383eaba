// Determinism is a contract: same seed → bit-identical trajectories, whatever the thread
// count; another seed → another run.
#include <gtest/gtest.h>

#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

std::string Swarm(int seed) {
  std::string arena =
      "<box id=\"w1\" size=\"0.1,4,0.5\" movable=\"false\"><body position=\"2,0,0\"/></box>"
      "<box id=\"w2\" size=\"0.1,4,0.5\" movable=\"false\"><body position=\"-2,0,0\"/></box>"
      "<box id=\"w3\" size=\"4,0.1,0.5\" movable=\"false\"><body position=\"0,2,0\"/></box>"
      "<box id=\"w4\" size=\"4,0.1,0.5\" movable=\"false\"><body position=\"0,-2,0\"/></box>"
      "<cylinder id=\"m\" radius=\"0.1\" height=\"0.2\" movable=\"true\" mass=\"0.5\"><body "
      "position=\"0.5,0.5,0\"/></cylinder>"
      "<distribute><position method=\"uniform\" min=\"-1.8,-1.8,0\" max=\"1.8,1.8,0\"/>"
      "<orientation method=\"uniform\" min=\"0,0,0\" max=\"360,0,0\"/>"
      "<entity quantity=\"30\" max_trials=\"100\"><foot-bot id=\"fb\"><controller "
      "config=\"c\"/></foot-bot></entity></distribute>";
  return Experiment(arena, WheelsController("c", "wander.lua"), 200, seed);
}

uint64_t RunHash(int seed, int threads) {
  TempDir d;
  d.Write("wander.lua", WanderController());
  LoadOptions lo;
  lo.threads = threads;
  Scene s = Load(d, Swarm(seed), lo);
  EXPECT_TRUE(s.ok()) << s.error;
  if (!s.ok()) return 0;
  while (Step(*s.world) == StepStatus::Running) {
  }
  EXPECT_EQ(s.world->tick, 200u);
  return PoseHash(*s.world);
}

TEST(Determinism, SameSeedSameTrajectories) { EXPECT_EQ(RunHash(11, 1), RunHash(11, 1)); }

TEST(Determinism, DifferentSeedDiffers) { EXPECT_NE(RunHash(11, 1), RunHash(12, 1)); }

TEST(Determinism, ThreadCountDoesNotChangeResults) {
  uint64_t one = RunHash(13, 1);
  EXPECT_EQ(one, RunHash(13, 2));
  EXPECT_EQ(one, RunHash(13, 4));
}

}  // namespace
}  // namespace essaim
