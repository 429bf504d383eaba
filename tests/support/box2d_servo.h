// Box2D worlds for tests that check Box2D itself: a robot as PhysicsWorld builds one, in
// bare Box2D calls.
#pragma once
#include <box2d/box2d.h>

namespace essaim::testing {

/// A foot-bot-sized disc (density 1) at `at`, tied by a friction joint to a kinematic servo
/// moving at `velocity`, as PhysicsWorld drives robots. Returns the disc.
inline b2Body* AddServoDisc(b2World* world, b2Vec2 at, b2Vec2 velocity, float max_force, float max_torque,
                            bool allow_sleep = true) {
  b2BodyDef bd;
  bd.type = b2_dynamicBody;
  bd.allowSleep = allow_sleep;
  bd.position = at;
  b2Body* body = world->CreateBody(&bd);
  b2CircleShape c;
  c.m_radius = 0.085f;
  body->CreateFixture(&c, 1.0f);
  b2BodyDef kd;
  kd.type = b2_kinematicBody;
  kd.position = bd.position;
  b2Body* control = world->CreateBody(&kd);
  control->SetLinearVelocity(velocity);
  b2FrictionJointDef jd;
  jd.bodyA = control;
  jd.bodyB = body;
  jd.maxForce = max_force;
  jd.maxTorque = max_torque;
  world->CreateJoint(&jd);
  return body;
}

}  // namespace essaim::testing
