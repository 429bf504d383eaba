// Dormant robots: a free robot (physics_free_robots.cpp) whose body has no contact at all, not
// even a non-touching one, is still an island of one body for Box2D each sub-step: its
// integration, transform (two sincosf), fixture sync and broadphase check, about 0.13 µs a
// sub-step for a few additions. Such a robot is put to sleep in Box2D for as long as Box2D's
// result for it is known without Box2D, and moved here, term for term as b2Island::Solve
// moves a lone body, so that results stay bit for bit those of stepping it:
// - its servo is solved here already (SolveServo), its forces and the world's gravity are
//   zero, its damping is Box2D's default zero (factor 1);
// - a sleeping body takes part in nothing: not in islands, not in Collide (it has no
//   contact), and its broad-phase proxy stays where it is. A sub-step is done here only if
//   Box2D's SynchronizeFixtures would not have moved that proxy either (CanSleepAt,
//   b2DynamicTree::MoveProxy's test), so the tree, its move buffer and every pair Box2D finds
//   stay the same; a pair found with the robot (another body's proxy moved onto it) gives it
//   a contact, and it wakes before the next sub-step's Collide;
// - waking puts its pose back with SetTransform, which must not move the proxy either: a
//   sub-step is only done here if its end pose can be put back so (CanSleepAt).
// Continuous collision is off (physics_world.cpp), so no time-of-impact pass reads a sweep.
#include <box2d/box2d.h>

#include "model/model.h"
#include "physics/physics_world.h"
#include "physics/physics_world_impl.h"

namespace essaim {

namespace {
/// b2Fixture keeps its proxies protected; its broad-phase proxy id is needed to read the
/// tree's fat box (a pointer to member taken through a derived class is the standard way).
struct FixtureAccess : b2Fixture {
  static constexpr b2FixtureProxy* b2Fixture::*kProxies = &FixtureAccess::m_proxies;
};

const b2AABB& TreeBox(b2Body* body) {
  const b2Fixture* f = body->GetFixtureList();  // a robot's body has its one circle
  const b2BroadPhase& bp = body->GetWorld()->GetContactManager().m_broadPhase;
  return bp.GetFatAABB((f->*FixtureAccess::kProxies)[0].proxyId);
}

/// A circle's box at `c`: b2CircleShape::ComputeAABB (the centre's offset is zero).
b2AABB CircleBox(b2Vec2 c, float r) {
  b2AABB box;
  box.lowerBound.Set(c.x - r, c.y - r);
  box.upperBound.Set(c.x + r, c.y + r);
  return box;
}

/// Whether a sub-step ending at `c` can be done here: Box2D's SynchronizeFixtures after it
/// would not move the proxy, nor would SetTransform at `c` on waking. The second is
/// b2DynamicTree::MoveProxy's test (Box2D 2.4.1, same float operations) for the box at `c`
/// with no displacement (a zero displacement adds +0 to the fat box's upper bounds, which
/// no comparison sees). It implies the first: the swept box of the sub-step is the union of
/// the box at its start, which the tree box holds (the pose was last synced there), and the
/// box at `c`; and the "huge" box MoveProxy grows from that union and a displacement holds
/// the one grown from the box at `c` alone (float rounding is monotonic).
bool CanSleepAt(const b2AABB& tree, b2Vec2 c, float r) {
  const b2AABB box = CircleBox(c, r);
  if (!tree.Contains(box)) return false;
  const b2Vec2 ext(b2_aabbExtension, b2_aabbExtension);
  b2AABB huge;  // MoveProxy's fat box, grown by four times its margin
  huge.lowerBound = (box.lowerBound - ext) - 4.0f * ext;
  huge.upperBound = (box.upperBound + ext) + 4.0f * ext;
  return huge.Contains(tree);
}

/// b2Island::Solve for a lone dynamic body with no force, gravity or damping: velocity
/// integration (adding the zero force turns a -0 component into +0, as Box2D's does), the
/// large-velocity clamps, then the position.
void IntegrateLone(PhysicsWorld::Impl::FreeServo* s, float h) {
  s->vel += h * s->inv_mass * b2Vec2(0.0f, 0.0f);
  s->spin += h * s->inv_moment * 0.0f;
  const b2Vec2 translation = h * s->vel;
  if (b2Dot(translation, translation) > b2_maxTranslationSquared) s->vel *= b2_maxTranslation / translation.Length();
  const float rotation = h * s->spin;
  if (rotation * rotation > b2_maxRotationSquared) s->spin *= b2_maxRotation / b2Abs(rotation);
  s->c += h * s->vel;
  s->a += h * s->spin;
}

/// One sub-step of `s` done here, or false (and `s` untouched) where Box2D's proxy would move.
bool TryDormantSubstep(PhysicsWorld::Impl::FreeServo* s, float h, float dt_ratio) {
  const float r = static_cast<float>(footbot::kRadius);
  PhysicsWorld::Impl::FreeServo next = *s;
  SolveServo(&next.vel, &next.spin, h, dt_ratio, &next);
  IntegrateLone(&next, h);
  if (!CanSleepAt(s->tree, next.c, r)) return false;
  *s = next;
  return true;
}
}  // namespace

bool DormantSubstep(b2Body* body, PhysicsWorld::Impl::FreeServo* s, float h, float dt_ratio) {
  if (body->GetContactList() != nullptr) return false;
  if (!s->dormant) {
    s->c = body->GetPosition();  // Box2D's sweep centre: the centre of mass is the origin
    s->a = body->GetAngle();
    s->vel = body->GetLinearVelocity();
    s->spin = body->GetAngularVelocity();
    s->tree = TreeBox(body);
    if (!TryDormantSubstep(s, h, dt_ratio)) return false;
    body->SetAwake(false);
    s->dormant = true;
    return true;
  }
  return TryDormantSubstep(s, h, dt_ratio);
}

void WakeDormant(b2Body* body, PhysicsWorld::Impl::FreeServo* s, float shift) {
  b2Vec2 c = s->c;
  float a = s->a;
  // PhysicsWorld::ShiftDynamicBodies' move, for a body it would shift.
  if (shift != 0 && (s->vel.x != 0 || s->vel.y != 0 || s->spin != 0)) {
    c = c + shift * s->vel;
    a = a + shift * s->spin;
  }
  body->SetTransform(c, a);
  body->SetAwake(true);
  body->SetLinearVelocity(s->vel);
  body->SetAngularVelocity(s->spin);
  s->dormant = false;
}

void PhysicsWorld::SetDormancy(bool on) { impl_->dormancy = on; }

int64_t PhysicsWorld::DormantSubsteps() const { return impl_->dormant_substeps; }

}  // namespace essaim
