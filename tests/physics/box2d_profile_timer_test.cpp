// physics/box2d_profile_timer.cpp replaces Box2D's profiling timer by ELF interposition.
// This checks the replacement is what libbox2d itself calls (not only what we call), and
// that it does not touch the process's clock.
#include <box2d/box2d.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include "support/box2d_servo.h"

namespace {

using Clock = std::chrono::steady_clock;
double Ms(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }

TEST(Box2dProfileTimer, LibraryStepsReadNoClock) {
  // Many islands, as robots make: each dynamic body tied to its own kinematic body.
  b2World world(b2Vec2(0, 0));
  for (int i = 0; i < 400; ++i) {
    const b2Vec2 at(static_cast<float>(i % 20), static_cast<float>(i / 20));
    essaim::testing::AddServoDisc(&world, at, b2Vec2(0.1f, 0), 15, 0.15f);
  }
  const Clock::time_point start = Clock::now();
  double slowest_ms = 0;
  for (int i = 0; i < 20; ++i) {
    const Clock::time_point a = Clock::now();
    world.Step(0.01f, 4, 2);
    slowest_ms = std::max(slowest_ms, Ms(a, Clock::now()));
  }
  // A live timer (µs resolution) would have measured something: a step of 400 islands
  // takes tens of µs.
  ASSERT_GT(slowest_ms, 0.005);
  const b2Profile& p = world.GetProfile();
  EXPECT_EQ(p.step, 0.0f);
  EXPECT_EQ(p.collide, 0.0f);
  EXPECT_EQ(p.solve, 0.0f);
  EXPECT_EQ(p.solveInit, 0.0f);
  EXPECT_EQ(p.solveVelocity, 0.0f);
  EXPECT_EQ(p.solvePosition, 0.0f);
  EXPECT_EQ(p.broadphase, 0.0f);
  // The bodies did move: the solver ran.
  EXPECT_GT(world.GetBodyList()->GetPosition().x + world.GetBodyList()->GetNext()->GetPosition().x, 0.0f);
  // The process's own clock is untouched.
  std::this_thread::sleep_for(std::chrono::milliseconds(2));
  EXPECT_GE(Ms(start, Clock::now()), 2.0);
}

TEST(Box2dProfileTimer, TimerReadsZero) {
  b2Timer t;
  std::this_thread::sleep_for(std::chrono::milliseconds(2));
  EXPECT_EQ(t.GetMilliseconds(), 0.0f);
}

}  // namespace
