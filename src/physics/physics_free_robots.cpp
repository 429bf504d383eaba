// Free robots: a robot that touches nothing and is tied by no grip is, in Box2D, an island of
// its body, its kinematic servo body and the friction joint between them; solving it costs
// an island, the joint's set-up and four velocity passes, and the servo body's integration
// and broadphase sync, every sub-step, for what is plain arithmetic on one body. Here that
// arithmetic runs before the step, term for term as b2FrictionJoint does it for a lone body
// (the terms that the servo's infinite mass and the centred anchors make zero are left out:
// adding a zero changes no value), and the servo body is disabled, which takes its joint
// out of Box2D's islands: Box2D then only integrates the robot's position from the velocity
// left here, as it would have. A robot that touches something gets its servo back and Box2D
// solves it with the joint; the joint then warm-starts from its impulse of the last sub-step
// Box2D solved it in, not the one carried here (the one inexact step of the scheme).
#include <box2d/box2d.h>

#include <cstring>

#include "physics/argos_dynamics.h"
#include "physics/physics_world.h"
#include "physics/physics_world_impl.h"

namespace essaim {

namespace {
/// Whether Box2D would put `body` in an island with another body this sub-step: a contact
/// touching at the bodies' poses now (Box2D's Collide evaluates the same manifold from the
/// same transforms at the step's start), sensors aside as Box2D's island search does. A
/// contact whose boxes stopped overlapping would be destroyed instead: counting it only
/// leaves the robot to Box2D, which is always exact.
bool Touches(b2Body* body) {
  for (b2ContactEdge* ce = body->GetContactList(); ce; ce = ce->next) {
    b2Contact* c = ce->contact;
    const b2Fixture* a = c->GetFixtureA();
    const b2Fixture* b = c->GetFixtureB();
    if (a->IsSensor() || b->IsSensor()) continue;
    b2Manifold m;
    c->Evaluate(&m, a->GetBody()->GetTransform(), b->GetBody()->GetTransform());
    if (m.pointCount > 0) return true;
  }
  return false;
}

template <class T>
bool SameBits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}
}  // namespace

// b2FrictionJoint::InitVelocityConstraints (warm start scaled by `dt_ratio`), then
// kVelocityIterations of SolveVelocityConstraints, both anchors at the centres.
void SolveServo(b2Vec2* v, float* w, float h, float dt_ratio, PhysicsWorld::Impl::FreeServo* s) {
  const float mB = s->inv_mass, iB = s->inv_moment;
  float det = mB * mB;  // b2Mat22::GetInverse of K = diag(mB, mB)
  if (det != 0.0f) det = 1.0f / det;
  const float linear_mass = det * mB;
  const float angular_mass = 1.0f / iB;
  b2Vec2 vB = *v;
  float wB = *w;
  s->linear *= dt_ratio;
  s->angular *= dt_ratio;
  vB += mB * s->linear;
  wB += iB * s->angular;
  const float max_angular = h * s->max_torque;
  const float max_linear = h * s->max_force;
  for (int k = 0; k < dyn2d::kVelocityIterations; ++k) {
    const float old_angular = s->angular, old_w = wB;
    const b2Vec2 old_linear = s->linear, old_v = vB;
    s->angular = b2Clamp(s->angular + -angular_mass * (wB - s->w), -max_angular, max_angular);
    wB += iB * (s->angular - old_angular);
    const b2Vec2 cdot = vB - s->v;
    s->linear += -b2Vec2(linear_mass * cdot.x, linear_mass * cdot.y);
    if (s->linear.LengthSquared() > max_linear * max_linear) {
      s->linear.Normalize();
      s->linear *= max_linear;
    }
    vB += mB * (s->linear - old_linear);
    // A pass that changed no bit is a fixed point: the passes left would change none either
    // (a robot at its servo's speed reaches one after a pass or two).
    if (SameBits(s->angular, old_angular) && SameBits(wB, old_w) && SameBits(s->linear, old_linear) &&
        SameBits(vB, old_v))
      break;
  }
  *v = vB;
  *w = wB;
}

namespace {
const b2FrictionJoint& ServoJoint(const b2Body* servo) {
  return *static_cast<const b2FrictionJoint*>(servo->GetJointList()->joint);
}

/// Marks, with this sub-step's stamp, the robots that hold or are locked and what they hold.
void MarkTied(PhysicsWorld::Impl* im) {
  for (int r : im->grip_robots) {
    im->free_servos[r].tied_at = im->substep_stamp;
    const GripTarget& t = im->grips[r].target;
    if (t.kind == BodyKind::Robot) im->free_servos[t.index].tied_at = im->substep_stamp;
  }
}
}  // namespace

void SolveFreeServos(PhysicsWorld::Impl* im, const std::vector<void*>& robots, bool first, float h) {
  b2World& w = *im->regions[0].world;
  // The tick's shift moved bodies since the last step: a zero step finds their new contacts
  // and evaluates them, as the coming step would (again, to the same result), and solves nothing.
  if (first) w.Step(0.0f, dyn2d::kVelocityIterations, dyn2d::kPositionIterations);
  ++im->substep_stamp;
  MarkTied(im);
  const float dt_ratio = im->inv_dt0 * h;  // b2World::Step's step.dtRatio
  // Grips read and move bodies between sub-steps: no robot sleeps in a tick that has one.
  const bool dormancy = im->dormancy && im->grip_robots.empty();
  for (size_t i = 0; i < robots.size(); ++i) {
    b2Body* body = AsBody(robots[i]);
    PhysicsWorld::Impl::FreeServo& s = im->free_servos[i];
    if (s.dormant) {
      if (DormantSubstep(body, &s, h, dt_ratio) && ++im->dormant_substeps) continue;
      WakeDormant(body, &s, 0);
    }
    if (s.tied_at == im->substep_stamp || Touches(body)) {
      if (s.free) im->controls[i]->SetEnabled(true);
      s.free = false;
      continue;
    }
    if (!s.free) {
      // The joint's accumulated impulses, as Box2D would warm-start them (exact: times 1).
      b2Body* servo = im->controls[i];
      const b2FrictionJoint& joint = ServoJoint(servo);
      s.linear = joint.GetReactionForce(1.0f);
      s.angular = joint.GetReactionTorque(1.0f);
      servo->SetEnabled(false);
      s.free = true;
    }
    if (dormancy && DormantSubstep(body, &s, h, dt_ratio) && ++im->dormant_substeps) continue;
    b2Vec2 v = body->GetLinearVelocity();
    float w = body->GetAngularVelocity();
    SolveServo(&v, &w, h, dt_ratio, &s);
    body->SetLinearVelocity(v);
    body->SetAngularVelocity(w);
  }
}

}  // namespace essaim
