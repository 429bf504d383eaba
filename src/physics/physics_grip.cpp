// The foot-bot gripper in the physics: its disc, and the hold as ARGoS's dynamics2d makes it
// (dynamics2d_gripping.cpp, CDynamics2DGripper): a locked gripper that touches a grippable
// shape ties it with a damped spring (Chipmunk 6's cpDampedSpring) from the robot's centre to
// the mean contact point, rest length their distance then; an unlocked one lets go at its
// disc's next contact with a grippable shape. The spring holds one distance only: the held
// body keeps its own orientation and floor friction, collides with the robot, turns about
// nothing, and stretches under load. Decisions are taken before each sub-step from the poses
// Chipmunk would meet (PhysicsWorld::Step's shift); a grip acts from the next sub-step on and
// a release after the current one, as ARGoS's post-step callbacks add and remove the spring.
#include <box2d/b2_distance.h>
#include <box2d/box2d.h>

#include <climits>
#include <cmath>

#include "physics/argos_dynamics.h"
#include "physics/physics_world.h"
#include "physics/physics_world_impl.h"

namespace essaim {

namespace {
/// stiffness · inverse mass · h², below which the spring's impulse is Chipmunk's explicit one
/// (SpringImpulses): 0.4 for ARGoS's 50 sub-steps a tick and a 0.1 kg object; the explicit
/// step diverges near 4.
constexpr double kExplicitLimit = 2;

/// The disc ahead of the turret at rotation `turret`, in the robot's frame.
b2Vec2 GripperDiscCentre(double turret) {
  return b2Vec2(static_cast<float>(footbot::kRadius * std::cos(turret)),
                static_cast<float>(footbot::kRadius * std::sin(turret)));
}

/// Where robot `robot`'s disc (`disc`: its body) has its centre now, in the world.
b2Vec2 DiscCentre(const b2Body* robot, const b2Body* disc) {
  const b2Fixture* f = disc->GetFixtureList();
  return b2Mul(robot->GetTransform(), static_cast<const b2CircleShape*>(f->GetShape())->m_p);
}

// Grippable fixtures overlapping the gripper disc; keeps the deepest (ties: robots before
// obstacles, then lower index), so the choice never depends on the tree's order. Ghosts
// (kind None) and static shapes are not grippable, nor the robot's own body and discs.
class GripQuery : public b2QueryCallback {
 public:
  GripQuery(const b2Vec2& centre, int self) : centre_(centre), self_(self) {}
  bool ReportFixture(b2Fixture* f) override {
    uintptr_t tag = f->GetUserData().pointer;
    BodyKind kind = TagKind(tag);
    int index = TagIndex(tag);
    if ((kind == BodyKind::Robot && index == self_) || kind == BodyKind::Gripper) return true;
    if (kind == BodyKind::None || f->GetBody()->GetType() != b2_dynamicBody) return true;
    b2DistanceInput in;
    in.proxyA.Set(&centre_, 1, 0.0f);
    in.proxyB.Set(f->GetShape(), 0);
    in.transformA.SetIdentity();
    in.transformB = f->GetBody()->GetTransform();
    in.useRadii = false;
    b2SimplexCache cache;
    cache.count = 0;
    b2DistanceOutput out;
    b2Distance(&out, &cache, &in);
    // Signed gap between the disc and the shape (its radius: circle radius, polygon skin).
    double gap = out.distance - f->GetShape()->m_radius - kGripperRadius;
    if (gap >= 0) return true;
    bool better = best.kind == BodyKind::None || gap < gap_ ||
                  (gap == gap_ &&
                   (static_cast<int>(kind) < static_cast<int>(best.kind) || (kind == best.kind && index < best.index)));
    if (better) {
      best.kind = kind;
      best.index = index;
      body = f->GetBody();
      gap_ = gap;
      core_point = out.pointB;
      surface_radius = f->GetShape()->GetType() == b2Shape::e_circle ? f->GetShape()->m_radius : 0;
    }
    return true;
  }
  GripTarget best;
  b2Body* body = nullptr;
  b2Vec2 core_point{0, 0};   // the best shape's core point nearest the disc's centre
  float surface_radius = 0;  // ... and how far its surface lies beyond it (a circle's radius)

 private:
  b2Vec2 centre_;
  int self_;
  double gap_ = 0;
};

/// ARGoS's anchor (CalculateAnchor, Chipmunk's circle-circle and circle-polygon contacts):
/// halfway between the disc's deepest point in the shape and the shape's surface point
/// nearest the disc's centre. A polygon counts without Box2D's skin, as Chipmunk's has none.
b2Vec2 ContactPoint(const b2Vec2& disc, const GripQuery& q) {
  b2Vec2 n = disc - q.core_point;  // from the shape into the disc
  const float len = n.Normalize();
  if (len == 0) return disc;  // the disc's centre inside the shape's core: no direction
  const b2Vec2 surface = q.core_point + q.surface_radius * n;
  const b2Vec2 deepest = disc - static_cast<float>(kGripperRadius) * n;
  return 0.5f * (surface + deepest);
}
}  // namespace

b2Body* MakeGripperDisc(b2World* shelf, const b2Body* robot, int index) {
  // ARGoS's gripper is a second body pinned to the base, its shape a sensor that collides with
  // nothing (robots still touch walls with their body): here a body of its own that Box2D
  // never moves nor files (static, disabled: no broadphase proxy to update every sub-step),
  // put on its robot's pose after every step (SyncGripperDiscs) for the rays that meet it.
  // It lives in a world of its own that never steps: Box2D's step walks every body of its
  // world's list three times a sub-step, disabled ones too.
  b2BodyDef bd;
  bd.type = b2_staticBody;
  bd.enabled = false;
  bd.position = robot->GetPosition();
  bd.angle = robot->GetAngle();
  b2Body* body = shelf->CreateBody(&bd);
  b2CircleShape disc;
  disc.m_radius = static_cast<float>(kGripperRadius);
  disc.m_p = GripperDiscCentre(0);
  b2FixtureDef fd;
  fd.shape = &disc;
  fd.density = 0;
  fd.isSensor = true;
  fd.filter.maskBits = 0;  // were it ever filed: no contact is made for it, not even a sensor's
  fd.userData.pointer = PackTag(BodyKind::Gripper, index);
  body->CreateFixture(&fd);
  return body;
}

void SyncGripperDisc(PhysicsWorld::Impl* im, const b2Body* robot, int index) {
  // The robot's own angle: b2Rot::Set of the same float gives the same transform.
  im->discs[index]->SetTransform(robot->GetPosition(), robot->GetAngle());
}

void SyncGripperDiscs(PhysicsWorld::Impl* im, const std::vector<void*>& robots) {
  for (size_t i = 0; i < robots.size(); ++i) SyncGripperDisc(im, AsBody(robots[i]), static_cast<int>(i));
}

Vec2 PhysicsWorld::GripperPoint(int robot, double turret) const {
  const b2Body* b = AsBody(robots_[robot]);
  double a = b->GetAngle() + turret;
  return {b->GetPosition().x + footbot::kRadius * std::cos(a), b->GetPosition().y + footbot::kRadius * std::sin(a)};
}

Vec2 PhysicsWorld::GripperDiscPoint(int robot) const {
  const b2Vec2 p = DiscCentre(AsBody(robots_[robot]), impl_->discs[robot]);
  return {p.x, p.y};
}

void PhysicsWorld::SetGripperLocked(int robot, bool locked) { impl_->grips[robot].locked = locked; }

void PhysicsWorld::Release(int robot) {
  Impl::Grip& g = impl_->grips[robot];
  g.target = GripTarget();
  g.from = 0;
  g.until = INT_MAX;
}

void PhysicsWorld::SetGripTurret(int robot, double turret) {
  Impl::Grip& g = impl_->grips[robot];
  g.turn += WrapSigned(turret - g.turret);
  g.turret = turret;
  // The ray grid is refiled at the next query.
  static_cast<b2CircleShape*>(impl_->discs[robot]->GetFixtureList()->GetShape())->m_p = GripperDiscCentre(turret);
  ++impl_->shapes_moved;
}

GripTarget PhysicsWorld::Gripped(int robot) const { return impl_->grips[robot].target; }

void* PhysicsWorld::HeldBody(int robot) const {
  const GripTarget& t = impl_->grips[robot].target;
  if (!t.Holding()) return nullptr;
  return t.kind == BodyKind::Robot ? robots_[t.index] : obstacles_[t.index];
}

void PhysicsWorld::GripEvents(int region, int substep) {
  Impl& im = *impl_;
  // At a tick's start (region -1) every region's shapes are candidates, and a grip brings
  // what it takes into the gripper's region; between sub-steps, only the region's own.
  const b2World* own = region < 0 ? nullptr : im.regions[region].world.get();
  for (int r : im.grip_robots) {
    b2Body* self = AsBody(robots_[r]);
    if (own && self->GetWorld() != own) continue;
    Impl::Grip& g = im.grips[r];
    const bool holding = g.target.Holding();
    if (holding == g.locked || g.until != INT_MAX) continue;  // nothing to decide
    // ARGoS turns the gripper body at a velocity over the tick: before sub-step i it has
    // turned (i + 1) / substeps of the way (Chipmunk moves, then solves).
    const double turret = g.turret - g.turn * (1 - (substep + 1.0) / im.substeps);
    const b2Vec2 centre = b2Mul(self->GetTransform(), GripperDiscCentre(turret));
    GripQuery q(centre, r);
    b2AABB box;
    box.lowerBound = centre - b2Vec2(kGripperRadius, kGripperRadius);
    box.upperBound = centre + b2Vec2(kGripperRadius, kGripperRadius);
    if (own)
      im.regions[region].world->QueryAABB(&q, box);
    else
      for (Impl::Region& each : im.regions) each.world->QueryAABB(&q, box);
    if (!q.body) continue;
    if (holding) {  // unlocked: ARGoS lets go when the disc touches any grippable shape
      g.until = substep;
      continue;
    }
    const b2Vec2 anchor = ContactPoint(centre, q);
    b2Body* held = q.body;
    // The spring ties bodies of one world: what is gripped joins the gripper's region now.
    if (held->GetWorld() != self->GetWorld()) held = AsBody(MoveGripGroupVoid(q.best, im.RegionOfBody(self)));
    g.target = q.best;
    g.anchor = held->GetLocalPoint(anchor);
    g.rest = b2Distance(self->GetPosition(), anchor);
    g.from = substep + 1;
    held->SetAwake(true);
  }
}

namespace {
/// Chipmunk's cpDampedSpring over one sub-step of `h` seconds between the holder's centre
/// (ARGoS's gripper body, pinned to the base's centre) and `anchor` on `held`: the spring's
/// impulse (rest − length)·stiffness·h along the line, then the damper's, which takes the
/// fraction 1 − exp(−damping·h·k) of their approach speed along it, k being the line's
/// inverse mass as ARGoS's bodies give it (its gripper body's 0.08 kg on the holder's side).
/// That explicit step diverges once stiffness·m⁻¹·h² nears 4 (m⁻¹: the line's inverse mass,
/// the whole robot on the holder's side): a 0.1 kg object at ARGoS's default 10 sub-steps of
/// 10 ms is at 10.6, and would be flung off. From kExplicitLimit on, the spring's impulse is
/// the implicit (backward Euler) one instead: stable at any step, and more damped.
void SpringImpulses(b2Body* holder, b2Body* held, const b2Vec2& anchor, double rest, double stiffness, double h) {
  const b2Vec2 r2 = b2Mul(held->GetTransform().q, anchor);
  const b2Vec2 delta = held->GetPosition() + r2 - holder->GetPosition();
  const double length = delta.Length();
  if (length == 0) return;  // Chipmunk: no direction, no impulse
  const double nx = delta.x / length, ny = delta.y / length;
  const double rn = static_cast<double>(r2.x) * ny - static_cast<double>(r2.y) * nx;
  const double rotation = rn * rn / held->GetInertia();
  const double k = 1 / footbot::kGripperMass + 1 / held->GetMass() + rotation;
  const double damper = 1 - std::exp(-dyn2d::kGripDamping * h * k);
  auto apply = [&](double j) {  // j along n on the held body, −j on the holder
    const b2Vec2 impulse(static_cast<float>(j * nx), static_cast<float>(j * ny));
    holder->ApplyLinearImpulseToCenter(-impulse, true);
    held->ApplyLinearImpulse(impulse, held->GetPosition() + r2, true);
  };
  auto approach = [&] {  // m/s, the held end's speed away from the holder's centre
    const b2Vec2 va = holder->GetLinearVelocity();
    const b2Vec2 vb = held->GetLinearVelocityFromWorldPoint(held->GetPosition() + r2);
    return (vb.x - va.x) * nx + (vb.y - va.y) * ny;
  };
  const double stiffness_h2 = stiffness * h * h * (1 / holder->GetMass() + 1 / held->GetMass() + rotation);
  if (stiffness_h2 < kExplicitLimit)
    apply((rest - length) * stiffness * h);
  else
    apply(((rest - length) * stiffness * h - stiffness * h * h * approach()) / (1 + stiffness_h2));
  apply(-approach() * damper / k);
}
}  // namespace

void PhysicsWorld::ApplyGripSprings(int region, int substep, float h) {
  Impl& im = *impl_;
  const b2World* own = im.regions[region].world.get();
  for (int r : im.grip_robots) {
    const Impl::Grip& g = im.grips[r];
    b2Body* self = AsBody(robots_[r]);
    if (!g.target.Holding() || self->GetWorld() != own || substep < g.from || substep > g.until) continue;
    SpringImpulses(self, AsBody(HeldBody(r)), g.anchor, g.rest, im.gripping_rigidity, h);
  }
}

void PhysicsWorld::EndGripSubstep(int region, int substep) {
  Impl& im = *impl_;
  const b2World* own = im.regions[region].world.get();
  for (int r : im.grip_robots)
    if (im.grips[r].until == substep && AsBody(robots_[r])->GetWorld() == own) Release(r);
}

void PhysicsWorld::BeginGripTick(int substeps) {
  Impl& im = *impl_;
  im.substeps = substeps;
  im.grip_robots.clear();
  for (int r = 0; r < RobotCount(); ++r)
    if (im.grips[r].locked || im.grips[r].target.Holding()) im.grip_robots.push_back(r);
  if (!im.grip_robots.empty()) GripEvents(-1, 0);
}

void PhysicsWorld::EndGripTick() {
  for (Impl::Grip& g : impl_->grips) {
    g.from = 0;
    g.turn = 0;
  }
}

}  // namespace essaim
