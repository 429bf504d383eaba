// PhysicsWorld turns off Box2D's clearing of forces after each step, since essaim applies
// none. This checks the premise on Box2D itself: a crowd of servo-driven robots pushing
// each other and a wall moves bit for bit the same with and without the clearing.
#include <box2d/box2d.h>
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <vector>

#include "support/box2d_servo.h"

namespace {

/// 200 foot-bot-sized discs in a tight block, each tied to a kinematic servo driving it
/// towards a wall (and so into its neighbours), as PhysicsWorld builds robots.
std::unique_ptr<b2World> Crowd(bool clear_forces, std::vector<b2Body*>* bodies) {
  auto world = std::make_unique<b2World>(b2Vec2(0, 0));
  world->SetAutoClearForces(clear_forces);
  world->SetContinuousPhysics(false);
  b2BodyDef wd;
  wd.position.Set(2.0f, 0);
  b2Body* wall = world->CreateBody(&wd);
  b2PolygonShape box;
  box.SetAsBox(0.05f, 5);
  wall->CreateFixture(&box, 0);
  for (int i = 0; i < 200; ++i) {
    const b2Vec2 at(0.16f * static_cast<float>(i % 10), 0.16f * static_cast<float>(i / 10) - 1.6f);
    const b2Vec2 velocity(0.2f, 0.01f * static_cast<float>(i % 7));
    bodies->push_back(essaim::testing::AddServoDisc(world.get(), at, velocity, 1.5f, 0.01f, /*allow_sleep=*/false));
  }
  return world;
}

TEST(Box2dClearForces, WithoutAppliedForcesClearingChangesNothing) {
  std::vector<b2Body*> cleared, kept;
  auto a = Crowd(true, &cleared);
  auto b = Crowd(false, &kept);
  for (int step = 0; step < 300; ++step) {
    a->Step(0.01f, 4, 2);
    b->Step(0.01f, 4, 2);
  }
  for (size_t i = 0; i < cleared.size(); ++i) {
    const b2Transform& x = cleared[i]->GetTransform();
    const b2Transform& y = kept[i]->GetTransform();
    ASSERT_EQ(std::memcmp(&x, &y, sizeof x), 0) << "robot " << i;
    const b2Vec2 v = cleared[i]->GetLinearVelocity(), w = kept[i]->GetLinearVelocity();
    ASSERT_EQ(std::memcmp(&v, &w, sizeof v), 0) << "robot " << i;
  }
  // The crowd is packed against the wall: contacts did act on every step's solution.
  int touching = 0;
  for (b2Contact* c = a->GetContactList(); c; c = c->GetNext()) touching += c->IsTouching();
  EXPECT_GT(touching, 150);
}

}  // namespace
