// Several regions, between ticks: bodies migrate to the region holding their centre (with
// whatever grips tie them to), and each world's ghosts of the other regions' bodies near its
// own are made, moved or dropped. One thread, robots then obstacles in index order: the
// worlds after it depend only on the experiment, never on the thread count.
#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "model/physics_regions.h"
#include "physics/physics_world.h"
#include "physics/physics_world_impl.h"

namespace essaim {

namespace {
/// m: how much nearer than their reach over a tick two bodies of different regions must come
/// before each world holds the other's ghost (covers Box2D's contact skin, 2 × 0.005 m).
constexpr double kGhostSlack = 0.05;

/// A copy of `src` in `dst`: same pose, velocity, fixtures (in the same order) and mass. A
/// ghost is static or kinematic (never pushed by its world) and its fixtures carry no tag.
b2Body* CloneBody(const b2Body* src, b2World* dst, bool ghost) {
  b2BodyDef bd;
  bd.type = src->GetType();
  if (ghost && bd.type == b2_dynamicBody) bd.type = b2_kinematicBody;
  bd.position = src->GetPosition();
  bd.angle = src->GetAngle();
  bd.linearVelocity = src->GetLinearVelocity();
  bd.angularVelocity = src->GetAngularVelocity();
  bd.linearDamping = src->GetLinearDamping();
  bd.angularDamping = src->GetAngularDamping();
  bd.allowSleep = src->IsSleepingAllowed();
  bd.awake = src->IsAwake();
  bd.fixedRotation = src->IsFixedRotation();
  bd.bullet = src->IsBullet();
  bd.gravityScale = src->GetGravityScale();
  b2Body* body = dst->CreateBody(&bd);
  // Box2D lists fixtures newest first: create them oldest first to keep that order.
  std::vector<const b2Fixture*> fixtures;
  for (const b2Fixture* f = src->GetFixtureList(); f; f = f->GetNext()) fixtures.push_back(f);
  for (auto it = fixtures.rbegin(); it != fixtures.rend(); ++it) {
    const b2Fixture* f = *it;
    b2FixtureDef fd;
    fd.shape = f->GetShape();
    fd.friction = f->GetFriction();
    fd.restitution = f->GetRestitution();
    fd.restitutionThreshold = f->GetRestitutionThreshold();
    fd.density = f->GetDensity();
    fd.isSensor = f->IsSensor();
    fd.filter = f->GetFilterData();
    fd.userData.pointer = ghost ? 0 : const_cast<b2Fixture*>(f)->GetUserData().pointer;
    body->CreateFixture(&fd);
  }
  if (!ghost && bd.type == b2_dynamicBody) {
    b2MassData md;
    src->GetMassData(&md);
    body->SetMassData(&md);
  }
  return body;
}

/// The friction joint between `body` and `other` (a servo or a floor drag), or null.
b2FrictionJoint* FrictionJointWith(b2Body* body, const b2Body* other) {
  for (b2JointEdge* e = body->GetJointList(); e; e = e->next)
    if (e->other == other && e->joint->GetType() == e_frictionJoint) return static_cast<b2FrictionJoint*>(e->joint);
  return nullptr;
}

b2AABB BodyBox(const b2Body* body) {
  b2AABB box;
  box.lowerBound.Set(body->GetPosition().x, body->GetPosition().y);
  box.upperBound = box.lowerBound;
  for (const b2Fixture* f = body->GetFixtureList(); f; f = f->GetNext())
    for (int c = 0; c < f->GetShape()->GetChildCount(); ++c) {
      b2AABB piece;
      f->GetShape()->ComputeAABB(&piece, body->GetTransform(), c);
      box.Combine(piece);
    }
  return box;
}

bool Overlap(const b2AABB& a, const b2AABB& b, float margin) {
  return a.lowerBound.x - margin <= b.upperBound.x && b.lowerBound.x <= a.upperBound.x + margin &&
         a.lowerBound.y - margin <= b.upperBound.y && b.lowerBound.y <= a.upperBound.y + margin;
}

/// A ghost follows its body: same pose, and a kinematic one the same velocity.
void FollowBody(const b2Body* body, b2Body* ghost) {
  if (ghost->GetPosition() != body->GetPosition() || ghost->GetAngle() != body->GetAngle())
    ghost->SetTransform(body->GetPosition(), body->GetAngle());
  if (ghost->GetType() != b2_kinematicBody) return;
  ghost->SetLinearVelocity(body->GetLinearVelocity());
  ghost->SetAngularVelocity(body->GetAngularVelocity());
}

/// The migration and ghost pass over one PhysicsWorld's insides. Nodes number the bodies:
/// robots 0..N-1, then obstacles N..N+M-1.
class RegionSync {
 public:
  RegionSync(PhysicsWorld::Impl& im, std::vector<void*>& robots, std::vector<void*>& obstacles)
      : im_(im), robots_(robots), obstacles_(obstacles), n_(static_cast<int>(robots.size())) {}

  int Nodes() const { return n_ + static_cast<int>(obstacles_.size()); }
  b2Body* Body(int node) const { return AsBody(node < n_ ? robots_[node] : obstacles_[node - n_]); }
  b2Body*& Ghost(int node, int region) {
    return node < n_ ? im_.robot_ghosts[node][region] : im_.obstacle_ghosts[node - n_][region];
  }
  int NodeOf(const GripTarget& t) const { return t.kind == BodyKind::Robot ? t.index : n_ + t.index; }

  /// Groups the nodes tied by grips (union-find; a group's root is its lowest node, so its
  /// lowest-indexed robot when it has one) and notes each node's region now.
  void Prepare() {
    const int total = Nodes();
    im_.parent.resize(total);
    std::iota(im_.parent.begin(), im_.parent.end(), 0);
    for (int h = 0; h < n_; ++h)
      if (im_.grips[h].target.Holding()) Join(h, NodeOf(im_.grips[h].target));
    im_.current.resize(total);
    for (int k = 0; k < total; ++k) im_.current[k] = im_.RegionOfBody(Body(k));
    im_.owner.resize(total);
  }

  /// Each group goes where its root's centre is (outside every region: where it is).
  void ChooseOwners() {
    for (int k = 0; k < Nodes(); ++k) {
      const int root = Find(k);
      if (root != k) {
        im_.owner[k] = im_.owner[root];  // root < k: already chosen
        continue;
      }
      const b2Vec2 p = Body(k)->GetPosition();
      im_.owner[k] = RegionOf(im_.region_defs, {p.x, p.y}, im_.current[k]);
    }
  }

  /// The group of `node` goes to `region`; the others stay.
  void OwnGroup(int node, int region) {
    const int root = Find(node);
    for (int k = 0; k < Nodes(); ++k) im_.owner[k] = Find(k) == root ? region : im_.current[k];
  }

  /// Moves every node whose owner is not its region (a group moves whole: a grip's spring,
  /// no Box2D joint, ties bodies by index, in one world).
  void ApplyMoves() {
    for (int k = 0; k < Nodes(); ++k)
      if (Moves(k)) MoveNode(k, im_.owner[k]);
  }

  /// Ghosts: a body gets one in each other region whose moving bodies' box comes within
  /// reach of its own — how far two bodies can close in over a tick at the fastest speed
  /// now (commanded speeds included), twice, plus a slack — and loses it beyond.
  void UpdateGhosts(double dt, const PhysicsRunner& runner) {
    FileBodyBoxes(runner);
    const int regions = im_.RegionCount();
    im_.region_boxes.resize(regions);
    for (b2AABB& box : im_.region_boxes) {
      box.lowerBound.Set(b2_maxFloat, b2_maxFloat);
      box.upperBound.Set(-b2_maxFloat, -b2_maxFloat);
    }
    double reach = 0;  // m
    for (int k = 0; k < Nodes(); ++k) {
      const b2Body* b = Body(k);
      if (b->GetType() != b2_dynamicBody) continue;
      const b2AABB& box = im_.body_boxes[k];
      im_.region_boxes[im_.current[k]].Combine(box);
      double speed = b->GetLinearVelocity().Length();
      if (k < n_) speed = std::max<double>(speed, im_.controls[k]->GetLinearVelocity().Length());
      const double spin = std::abs(b->GetAngularVelocity()) * box.GetExtents().Length();
      reach = std::max(reach, (speed + spin) * dt);
    }
    const float margin = static_cast<float>(2 * reach + kGhostSlack);
    im_.ghost_pairs.resize(regions);
    for (auto& pairs : im_.ghost_pairs) pairs.clear();
    for (int k = 0; k < Nodes(); ++k) {
      b2Body* b = Body(k);
      const b2AABB& box = im_.body_boxes[k];
      for (int r = 0; r < regions; ++r) {
        b2Body*& ghost = Ghost(k, r);
        const bool want = r != im_.current[k] && Overlap(box, im_.region_boxes[r], margin);
        if (!want) {
          if (ghost) ghost->GetWorld()->DestroyBody(ghost);
          ghost = nullptr;
          continue;
        }
        if (!ghost)
          ghost = CloneBody(b, im_.regions[r].world.get(), true);
        else
          FollowBody(b, ghost);
        im_.ghost_pairs[r].emplace_back(b, ghost);
      }
    }
  }

 private:
  bool Moves(int k) const { return im_.owner[k] != im_.current[k]; }

  /// Recreates node k's body (a robot's with its servo, a movable obstacle's with its floor
  /// drag) in region r's world; its ghost there, if any, goes.
  void MoveNode(int k, int r) {
    b2Body* old = Body(k);
    PhysicsWorld::Impl::Region& to = im_.regions[r];
    if (b2Body*& ghost = Ghost(k, r)) {
      to.world->DestroyBody(ghost);
      ghost = nullptr;
    }
    b2Body* body = CloneBody(old, to.world.get(), false);
    const bool robot = k < n_;
    b2Body* other = robot ? im_.controls[k] : im_.regions[im_.current[k]].ground;
    if (const b2FrictionJoint* joint = FrictionJointWith(old, other)) {
      b2FrictionJointDef jd;
      jd.maxForce = joint->GetMaxForce();
      jd.maxTorque = joint->GetMaxTorque();
      if (robot) {
        jd.bodyA = CloneBody(other, to.world.get(), false);
        jd.bodyB = body;
        other->GetWorld()->DestroyBody(other);
        im_.controls[k] = jd.bodyA;
      } else {
        jd.Initialize(to.ground, body, body->GetPosition());
      }
      to.world->CreateJoint(&jd);
    }
    old->GetWorld()->DestroyBody(old);
    (robot ? robots_[k] : obstacles_[k - n_]) = body;
    im_.current[k] = r;
  }

  /// Every node's box, on the pool (reading bodies only; a wall tiled into many pieces
  /// costs one box per piece).
  void FileBodyBoxes(const PhysicsRunner& runner) {
    im_.body_boxes.resize(Nodes());
    auto job = [](void* ctx, int k) {
      RegionSync& sync = *static_cast<RegionSync*>(ctx);
      sync.im_.body_boxes[k] = BodyBox(sync.Body(k));
    };
    if (runner.run)
      runner.run(runner.pool, Nodes(), job, this);
    else
      for (int k = 0; k < Nodes(); ++k) job(this, k);
  }

  int Find(int k) {
    std::vector<int>& p = im_.parent;
    while (p[k] != k) k = p[k] = p[p[k]];
    return k;
  }
  void Join(int a, int b) {
    a = Find(a);
    b = Find(b);
    if (a != b) im_.parent[std::max(a, b)] = std::min(a, b);
  }

  PhysicsWorld::Impl& im_;
  std::vector<void*>& robots_;
  std::vector<void*>& obstacles_;
  const int n_;
};
}  // namespace

void PhysicsWorld::SyncRegions(double dt, const PhysicsRunner& runner) {
  RegionSync sync(*impl_, robots_, obstacles_);
  sync.Prepare();
  sync.ChooseOwners();
  sync.ApplyMoves();
  sync.UpdateGhosts(dt, runner);
  ++impl_->shapes_moved;
}

namespace {
void FollowRegionGhosts(void* ctx, int region) {
  const auto& pairs = (*static_cast<std::vector<std::vector<std::pair<b2Body*, b2Body*>>>*>(ctx))[region];
  for (const auto& [body, ghost] : pairs) FollowBody(body, ghost);
}
}  // namespace

// A ghost moves only its own region's world, and reads a body no one moves between sub-steps:
// the regions' ghosts follow at once.
void PhysicsWorld::FollowGhosts(const PhysicsRunner& runner) {
  const int regions = static_cast<int>(impl_->ghost_pairs.size());
  if (runner.run)
    runner.run(runner.pool, regions, &FollowRegionGhosts, &impl_->ghost_pairs);
  else
    for (int r = 0; r < regions; ++r) FollowRegionGhosts(&impl_->ghost_pairs, r);
}

void* PhysicsWorld::MoveGripGroupVoid(const GripTarget& t, int region) {
  RegionSync sync(*impl_, robots_, obstacles_);
  sync.Prepare();
  const int node = sync.NodeOf(t);
  sync.OwnGroup(node, region);
  sync.ApplyMoves();
  ++impl_->shapes_moved;
  return sync.Body(node);
}

}  // namespace essaim
