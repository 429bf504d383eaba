#include "physics/physics_world.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>

#include "model/physics_regions.h"
#include "physics/physics_world_impl.h"

namespace essaim {

namespace {
constexpr double kMaxStaticPiece = 1.0;    // m, longest side of one static box fixture
constexpr double kMaxStaticPieces = 4096;  // fixtures per static box (longer pieces beyond)
/// m, how far neighbouring pieces of a tiled wall overlap: far above their float rounding
/// (~6e-8 m at arena scale), far below anything a sensor resolves.
constexpr double kSeamOverlap = 1e-5;

/// m: the ray grid's cells, a side of about three foot-bot diameters. A scanner's disc
/// (1.51 m) spans 7 × 7 cells, the proximity ring's (0.19 m) one to four; smaller cells
/// file each robot in more of them, larger ones let more far shapes through.
constexpr double kRayCellSize = 0.5;
}  // namespace

namespace {
/// The friction a fixture holds for ARGoS's coefficient `argos`. A contact's friction is
/// Chipmunk's product of the two shapes' coefficients in ARGoS (foot-bot on wall 0.7 × 0.1 =
/// 0.07) and Box2D's square root of the product of the two fixtures'; fixtures holding the
/// squares give the product in every pair, every region, at no cost per contact.
float ContactFriction(double argos) { return static_cast<float>(argos * argos); }

/// One Box2D world per region, each with its ground body first.
void MakeRegionWorlds(size_t count, std::vector<PhysicsWorld::Impl::Region>* regions) {
  regions->resize(count);
  for (PhysicsWorld::Impl::Region& region : *regions) {
    region.world = std::make_unique<b2World>(b2Vec2(0, 0));
    // Continuous collision (time of impact) guards against tunnelling at speed; foot-bots
    // move millimetres per sub-step, so it only costs time (~5% of a 1000-robot step).
    region.world->SetContinuousPhysics(false);
    // essaim applies no forces (the servo is a joint), so the forces Box2D clears after
    // each step are always zero: its walk over every body to clear them is skipped.
    region.world->SetAutoClearForces(false);
    b2BodyDef gd;
    region.ground = region.world->CreateBody(&gd);
  }
}
}  // namespace

PhysicsWorld::PhysicsWorld(const Model& model) : impl_(std::make_unique<Impl>()) {
  const size_t region_count = std::max<size_t>(1, model.physics.regions.size());
  if (region_count > 1) impl_->region_defs = model.physics.regions;
  MakeRegionWorlds(region_count, &impl_->regions);

  impl_->phys = model.physics;
  const PhysicsDef& phys = model.physics;
  impl_->grips.resize(model.robots.size());
  impl_->gripping_rigidity = phys.gripping_rigidity;
  if (region_count > 1) impl_->robot_ghosts.assign(model.robots.size(), std::vector<b2Body*>(region_count, nullptr));
  // Sized once for what the model holds (loop functions may add obstacles later).
  obstacles_.reserve(model.obstacles.size());
  impl_->obstacle_top.reserve(model.obstacles.size());
  impl_->obstacle_bottom.reserve(model.obstacles.size());
  robots_.reserve(model.robots.size());
  impl_->controls.reserve(model.robots.size());
  for (const ObstacleDef& o : model.obstacles) AddObstacle(o);

  for (size_t i = 0; i < model.robots.size(); ++i) AddRobotBody(model.robots[i], static_cast<int>(i));
}

void PhysicsWorld::AddRobotBody(const RobotDef& r, int i) {
  b2World& w = *impl_->regions[RegionOf(impl_->region_defs, {r.pose.x, r.pose.y}, 0)].world;
  b2BodyDef bd;
  bd.type = b2_dynamicBody;
  bd.position.Set(static_cast<float>(r.pose.x), static_cast<float>(r.pose.y));
  // ARGoS turns the start yaw into a quaternion and back (-π..π) before its body takes it:
  // a robot placed at 300° starts at -60°, and its orientation quaternion says so.
  bd.angle = static_cast<float>(WrapSigned(r.pose.yaw));
  bd.allowSleep = false;  // ARGoS never sleeps robots; keeps the servo always live
  b2Body* body = w.CreateBody(&bd);
  b2CircleShape circle;
  circle.m_radius = static_cast<float>(footbot::kRadius);
  b2FixtureDef fd;
  fd.shape = &circle;
  fd.friction = ContactFriction(0.7);
  fd.restitution = 0;
  fd.density = static_cast<float>(footbot::kMass / (kPi * footbot::kRadius * footbot::kRadius));
  fd.userData.pointer = PackTag(BodyKind::Robot, i);
  body->CreateFixture(&fd);
  b2MassData md;
  md.mass = static_cast<float>(footbot::kMass);
  md.center.SetZero();
  // ARGoS's base and gripper bodies turn together (a gear joint) and both have the moment of
  // the base's mass with quirk 1, I = m (2r)^2 / 2: twice that about the centre.
  md.I = static_cast<float>(2 * footbot::kBaseMass * 4 * footbot::kRadius * footbot::kRadius / 2);
  body->SetMassData(&md);
  AddGripperDisc(body, i);

  // The servo: a kinematic body moving at the commanded velocity, tied to the robot by
  // a friction joint, which drives their relative velocity to zero with capped force
  // and torque — Chipmunk's pivot + gear with maxBias 0 in ARGoS.
  b2BodyDef cd;
  cd.type = b2_kinematicBody;
  cd.position = bd.position;
  cd.angle = bd.angle;
  b2Body* control = w.CreateBody(&cd);
  b2FrictionJointDef jd;
  jd.bodyA = control;
  jd.bodyB = body;
  jd.localAnchorA.SetZero();
  jd.localAnchorB.SetZero();
  jd.maxForce = static_cast<float>(r.max_force);
  jd.maxTorque = static_cast<float>(r.max_torque);
  w.CreateJoint(&jd);
  robots_.push_back(body);
  impl_->controls.push_back(control);
}

int PhysicsWorld::AddRobot(const RobotDef& robot) {
  const int index = RobotCount();
  impl_->grips.emplace_back();
  if (RegionCount() > 1) impl_->robot_ghosts.emplace_back(RegionCount(), nullptr);
  AddRobotBody(robot, index);
  ++impl_->shapes_moved;  // the ray grid files the new circles
  return index;
}

void PhysicsWorld::RemoveLastRobot() {
  b2Body* body = AsBody(robots_.back());
  body->GetWorld()->DestroyBody(impl_->controls.back());  // and the servo joint with it
  body->GetWorld()->DestroyBody(body);
  robots_.pop_back();
  impl_->controls.pop_back();
  impl_->grips.pop_back();
  if (RegionCount() > 1) impl_->robot_ghosts.pop_back();
  ++impl_->shapes_moved;
}

int PhysicsWorld::RegionCount() const { return impl_->RegionCount(); }

int PhysicsWorld::RobotRegion(int robot) const { return impl_->RegionOfBody(AsBody(robots_[robot])); }

namespace {
/// A long static wall's bounding box overlaps most of the tree and makes every ray cast
/// visit it (measured: 1.67 µs per ray with four 32 m walls, 0.46 µs split). Tiled into
/// pieces of at most kMaxStaticPiece, same body and tag: same hits, same distances. At
/// most kMaxStaticPieces pieces: a 1 km square would be a million fixtures. Neighbouring
/// pieces overlap by kSeamOverlap: their float vertices, rounded apart, left gaps of ~6e-8 m
/// that a ray along a seam went through into the wall (the outer faces do not move).
void TileStaticBox(const ObstacleDef& o, b2Body* body, b2FixtureDef* fd, b2PolygonShape* poly) {
  double piece = kMaxStaticPiece;
  while (std::ceil(o.size_x / piece) * std::ceil(o.size_y / piece) > kMaxStaticPieces) piece *= 2;
  const int nx = static_cast<int>(std::ceil(o.size_x / piece));
  const int ny = static_cast<int>(std::ceil(o.size_y / piece));
  // Piece k of n along a side of length `size`: its [lo, hi], inner ends widened.
  auto span = [](double size, int n, int k, double* lo, double* hi) {
    *lo = -size / 2 + size * k / n - (k > 0 ? kSeamOverlap : 0);
    *hi = -size / 2 + size * (k + 1) / n + (k + 1 < n ? kSeamOverlap : 0);
  };
  for (int ix = 0; ix < nx; ++ix)
    for (int iy = 0; iy < ny; ++iy) {
      double x0, x1, y0, y1;
      span(o.size_x, nx, ix, &x0, &x1);
      span(o.size_y, ny, iy, &y0, &y1);
      poly->SetAsBox(static_cast<float>((x1 - x0) / 2), static_cast<float>((y1 - y0) / 2),
                     b2Vec2(static_cast<float>((x0 + x1) / 2), static_cast<float>((y0 + y1) / 2)), 0);
      body->CreateFixture(fd);
    }
}

/// A long static box as two sets of fixtures: the whole box collides, tagged None (queries
/// and rays pass it by), and its pieces, sensors that collide with nothing, are what rays and
/// queries meet. Robots pressed on a wall overlap it a little, as ARGoS's do (1-2 mm); against
/// pieces they caught on the next piece's corner at each seam, where ARGoS's slide on.
void AddLongStaticBox(const ObstacleDef& o, b2Body* body, b2FixtureDef* fd, b2PolygonShape* poly) {
  b2FixtureDef whole = *fd;
  whole.userData.pointer = PackTag(BodyKind::None, 0);
  body->CreateFixture(&whole);
  fd->isSensor = true;
  fd->filter.maskBits = 0;  // no contact is ever made for a piece
  TileStaticBox(o, body, fd, poly);
}

/// The obstacle's box or circle fixture(s) on `body`, tagged with its index.
void AddObstacleFixtures(const ObstacleDef& o, int index, b2Body* body) {
  b2FixtureDef fd;
  b2PolygonShape poly;
  b2CircleShape circle;
  double area;
  if (o.kind == ShapeKind::Box) {
    poly.SetAsBox(static_cast<float>(o.size_x / 2), static_cast<float>(o.size_y / 2));
    // Box2D wraps polygons in a 1 cm skin (b2_polygonRadius) that collides but that rays do
    // not see: a robot placed within 5 mm of a static box was pushed off it at the first
    // step, where ARGoS leaves it. Without the skin a static box collides at its true
    // faces, as ARGoS's does (its pieces too: TileStaticBox copies this shape). Movable
    // boxes keep theirs: the issue was static ones, and box-on-box stacking relies on it.
    if (!o.movable) poly.m_radius = 0;
    fd.shape = &poly;
    area = o.size_x * o.size_y;
  } else {
    circle.m_radius = static_cast<float>(o.radius);
    fd.shape = &circle;
    area = kPi * o.radius * o.radius;
  }
  // ARGoS: static friction 0.1, movable 0.7, no bounce.
  fd.friction = ContactFriction(o.movable ? 0.7 : 0.1);
  fd.restitution = 0;
  fd.density = o.movable ? static_cast<float>(o.mass / area) : 0.0f;
  fd.userData.pointer = PackTag(BodyKind::Obstacle, index);
  if (o.kind == ShapeKind::Box && !o.movable && std::max(o.size_x, o.size_y) > kMaxStaticPiece)
    AddLongStaticBox(o, body, &fd, &poly);
  else
    body->CreateFixture(&fd);
}

/// A movable obstacle's mass (ARGoS's cylinder moment) and its floor friction: a drag
/// towards zero velocity with capped force and torque.
void MakeMovable(const ObstacleDef& o, const PhysicsDef& phys, b2World* world, b2Body* ground, b2Body* body) {
  if (o.kind == ShapeKind::Cylinder) {
    // ARGoS quirk 1: the moment uses the diameter as radius (4x a uniform disc).
    b2MassData md;
    md.mass = static_cast<float>(o.mass);
    md.center.SetZero();
    md.I = static_cast<float>(o.mass * (2 * o.radius) * (2 * o.radius) / 2);
    body->SetMassData(&md);
  }
  b2FrictionJointDef jd;
  jd.Initialize(ground, body, body->GetPosition());
  bool box = o.kind == ShapeKind::Box;
  jd.maxForce = static_cast<float>(box ? phys.box_linear_friction : phys.cylinder_linear_friction);
  jd.maxTorque = static_cast<float>(box ? phys.box_angular_friction : phys.cylinder_angular_friction);
  world->CreateJoint(&jd);
}
}  // namespace

int PhysicsWorld::AddObstacle(const ObstacleDef& o) {
  ++impl_->shapes_moved;
  const int index = static_cast<int>(obstacles_.size());
  b2BodyDef bd;
  bd.type = o.movable ? b2_dynamicBody : b2_staticBody;
  bd.position.Set(static_cast<float>(o.pose.x), static_cast<float>(o.pose.y));
  bd.angle = static_cast<float>(o.pose.yaw);
  Impl::Region& region = impl_->regions[RegionOf(impl_->region_defs, {o.pose.x, o.pose.y}, 0)];
  b2Body* body = region.world->CreateBody(&bd);
  AddObstacleFixtures(o, index, body);
  if (o.movable) MakeMovable(o, impl_->phys, region.world.get(), region.ground, body);
  obstacles_.push_back(body);
  if (impl_->RegionCount() > 1) impl_->obstacle_ghosts.emplace_back(impl_->RegionCount(), nullptr);
  impl_->obstacle_bottom.push_back(o.z);
  impl_->obstacle_top.push_back(o.z + o.height);
  return index;
}

void PhysicsWorld::RemoveObstacle(int index) {
  ++impl_->shapes_moved;
  b2Body* body = AsBody(obstacles_[index]);
  for (size_t r = 0; r < impl_->grips.size(); ++r) {
    GripTarget& t = impl_->grips[r].target;
    if (t.kind != BodyKind::Obstacle) continue;
    if (t.index == index)
      Release(static_cast<int>(r));
    else if (t.index > index)
      --t.index;
  }
  if (impl_->RegionCount() > 1) {
    for (b2Body* ghost : impl_->obstacle_ghosts[index])
      if (ghost) ghost->GetWorld()->DestroyBody(ghost);
    impl_->obstacle_ghosts.erase(impl_->obstacle_ghosts.begin() + index);
  }
  body->GetWorld()->DestroyBody(body);  // its fixtures and friction joint too
  obstacles_.erase(obstacles_.begin() + index);
  impl_->obstacle_top.erase(impl_->obstacle_top.begin() + index);
  impl_->obstacle_bottom.erase(impl_->obstacle_bottom.begin() + index);
  // Fixture tags carry the index: those after the removed one move down by one.
  for (size_t k = index; k < obstacles_.size(); ++k)
    for (b2Fixture* f = AsBody(obstacles_[k])->GetFixtureList(); f; f = f->GetNext())
      if (TagKind(f->GetUserData().pointer) == BodyKind::Obstacle)  // not a long box's whole
        f->GetUserData().pointer = PackTag(BodyKind::Obstacle, static_cast<int>(k));
}

void PhysicsWorld::SetObstaclePose(int index, const Pose2& pose) {
  ++impl_->shapes_moved;
  b2Body* b = AsBody(obstacles_[index]);
  b->SetTransform(b2Vec2(static_cast<float>(pose.x), static_cast<float>(pose.y)), static_cast<float>(pose.yaw));
  b->SetLinearVelocity(b2Vec2(0, 0));
  b->SetAngularVelocity(0);
  b->SetAwake(true);
}

PhysicsWorld::~PhysicsWorld() = default;

void PhysicsWorld::SetWheelSpeeds(int robot, double left, double right) {
  b2Body* body = AsBody(robots_[robot]);
  b2Body* control = impl_->controls[robot];
  if (left == 0 && right == 0) {
    control->SetLinearVelocity(b2Vec2(0, 0));
    control->SetAngularVelocity(0);
    return;
  }
  double a = body->GetAngle();
  double v = (left + right) / 2;
  double w = (right - left) / footbot::kAxisLength;
  control->SetLinearVelocity(b2Vec2(static_cast<float>(v * std::cos(a)), static_cast<float>(v * std::sin(a))));
  control->SetAngularVelocity(static_cast<float>(w));
}

namespace {
struct RegionSteps {
  PhysicsWorld* world;
  float h;
  int first, count;  // sub-steps first .. first + count - 1 of the tick
};
}  // namespace

void PhysicsWorld::StepRegionJob(void* ctx, int region) {
  const RegionSteps& s = *static_cast<const RegionSteps*>(ctx);
  s.world->StepRegion(region, s.first, s.count, s.h);
}

void PhysicsWorld::StepRegion(int region, int first, int count, float h) {
  // 4 velocity and 2 position iterations per sub-step: with ARGoS's 10 sub-steps that is 40
  // solver passes per tick; 8/3 cost 9% more instructions with no change in any test.
  b2World& w = *impl_->regions[region].world;
  const bool grips = !impl_->grip_robots.empty();
  for (int i = first; i < first + count; ++i) {
    if (grips) {
      if (i > 0) GripEvents(region, i);  // sub-step 0's were taken for every region at once
      ApplyGripSprings(region, i, h);
    }
    w.Step(h, 4, 2);
    if (grips) EndGripSubstep(region, i);
  }
}

namespace {
/// Moves a moving dynamic body by `h` seconds at its velocity (h < 0: back).
void ShiftAlongVelocity(void* p, float h) {
  b2Body* body = AsBody(p);
  const b2Vec2 v = body->GetLinearVelocity();
  const float w = body->GetAngularVelocity();
  if (body->GetType() != b2_dynamicBody || (v.x == 0 && v.y == 0 && w == 0)) return;
  body->SetTransform(body->GetPosition() + h * v, body->GetAngle() + h * w);
}
}  // namespace

// ARGoS's engine (Chipmunk) moves each body at the start of a sub-step with the velocity the
// sub-step before solved, then solves velocities; Box2D solves, then moves. So Box2D's pose
// after a sub-step is Chipmunk's after the next one's move, and the two engines meet the same
// contacts at the same places when Box2D's bodies are one sub-step ahead along their velocity.
// Between ticks the bodies hold ARGoS's poses, which everything else reads (sensors, the
// wheels' heading, loop functions); a tick shifts them ahead, steps, and shifts them back.
void PhysicsWorld::ShiftDynamicBodies(float h) {
  for (void* body : robots_) ShiftAlongVelocity(body, h);
  for (void* body : obstacles_) ShiftAlongVelocity(body, h);
}

void PhysicsWorld::Step(double dt, int substeps, const PhysicsRunner& runner) {
  const float h = static_cast<float>(dt / substeps);
  ShiftDynamicBodies(h);
  BeginGripTick(substeps);
  if (impl_->RegionCount() == 1)
    StepRegion(0, 0, substeps, h);
  else
    StepRegions(dt, substeps, runner);
  EndGripTick();
  ShiftDynamicBodies(-h);
  ++impl_->shapes_moved;
}

void PhysicsWorld::StepRegions(double dt, int substeps, const PhysicsRunner& runner) {
  const int regions = impl_->RegionCount();
  SyncRegions(dt, runner);
  // The regions step one sub-step at a time, the ghosts following their bodies in between:
  // a ghost moves at its body's velocity of the sub-step's start, never a tick's.
  // Each region's world is its own: stepping them at once writes nothing they share.
  RegionSteps steps{this, static_cast<float>(dt / substeps), 0, 1};
  for (int i = 0; i < substeps; ++i) {
    if (i > 0) FollowGhosts(runner);
    steps.first = i;
    if (runner.run)
      runner.run(runner.pool, regions, &StepRegionJob, &steps);
    else
      for (int r = 0; r < regions; ++r) StepRegionJob(&steps, r);
  }
}

Pose2 PhysicsWorld::RobotPose(int robot) const {
  const b2Body* b = AsBody(robots_[robot]);
  return {b->GetPosition().x, b->GetPosition().y, b->GetAngle()};
}

Vec2 PhysicsWorld::RobotVelocity(int robot) const {
  const b2Vec2 v = AsBody(robots_[robot])->GetLinearVelocity();
  return {v.x, v.y};
}

double PhysicsWorld::RobotAngularVelocity(int robot) const { return AsBody(robots_[robot])->GetAngularVelocity(); }

void PhysicsWorld::SetRobotPose(int robot, const Pose2& pose) {
  ++impl_->shapes_moved;
  b2Body* b = AsBody(robots_[robot]);
  const b2Transform before = b->GetTransform();
  const float yaw = static_cast<float>(WrapSigned(pose.yaw));  // as a start yaw (AddRobot)
  const float turn = yaw - b->GetAngle();
  b->SetTransform(b2Vec2(static_cast<float>(pose.x), static_cast<float>(pose.y)), yaw);
  b->SetLinearVelocity(b2Vec2(0, 0));
  b->SetAngularVelocity(0);
  // A held object moves with the robot instead of being dragged across the arena.
  if (impl_->grips[robot].target.Holding()) {
    b2Body* held = AsBody(HeldBody(robot));
    b2Vec2 local = b2MulT(before, held->GetPosition());
    held->SetTransform(b2Mul(b->GetTransform(), local), held->GetAngle() + turn);
    held->SetLinearVelocity(b2Vec2(0, 0));
    held->SetAngularVelocity(0);
  }
}

Pose2 PhysicsWorld::ObstaclePose(int obstacle) const {
  const b2Body* b = AsBody(obstacles_[obstacle]);
  return {b->GetPosition().x, b->GetPosition().y, b->GetAngle()};
}

void PhysicsWorld::FreezeRobot(int robot) { SetWheelSpeeds(robot, 0, 0); }

namespace {
/// A shape's vertical extent (m): a robot's is the foot-bot's body, an obstacle's its own.
void HeightSpan(BodyKind kind, int index, const std::vector<double>& tops, const std::vector<double>& bottoms,
                double* bottom, double* top) {
  if (kind == BodyKind::Robot || kind == BodyKind::Gripper) {
    *bottom = 0;
    *top = footbot::kHeight;
  } else {
    *bottom = bottoms[index];
    *top = tops[index];
  }
}

/// Whether a query at height z can touch this shape: any robot but the excluded one, any
/// obstacle, whose vertical extent contains z.
bool ReachesHeight(BodyKind kind, int index, double z, int exclude_robot, const std::vector<double>& tops,
                   const std::vector<double>& bottoms) {
  if (kind == BodyKind::None || (kind != BodyKind::Obstacle && index == exclude_robot)) return false;
  double bottom, top;
  HeightSpan(kind, index, tops, bottoms, &bottom, &top);
  return z >= bottom && z <= top;
}

class ClosestRay : public b2RayCastCallback {
 public:
  ClosestRay(const std::vector<double>& tops, const std::vector<double>& bottoms, double z, int exclude)
      : tops_(tops), bottoms_(bottoms), z_(z), exclude_(exclude) {}
  float ReportFixture(b2Fixture* f, const b2Vec2& point, const b2Vec2&, float fraction) override {
    uintptr_t tag = f->GetUserData().pointer;
    BodyKind kind = TagKind(tag);
    int index = TagIndex(tag);
    if (!ReachesHeight(kind, index, z_, exclude_, tops_, bottoms_)) return -1;
    if (fraction > fraction_) return -1;  // a farther hit in a later region's world
    hit.kind = kind;
    hit.index = index;
    hit.point = {point.x, point.y};
    fraction_ = fraction;
    return fraction;  // clip: keep looking for closer hits only
  }
  RayHit hit;
  float fraction_ = 1;

 private:
  const std::vector<double>& tops_;
  const std::vector<double>& bottoms_;
  double z_;
  int exclude_;
};

class RobotQuery : public b2QueryCallback {
 public:
  RobotQuery(const Vec2& c, double r, std::vector<int>* out) : c_(c), r2_(r * r), out_(out) {}
  bool ReportFixture(b2Fixture* f) override {
    uintptr_t tag = f->GetUserData().pointer;
    if (TagKind(tag) != BodyKind::Robot) return true;
    b2Vec2 p = f->GetBody()->GetPosition();
    if ((Vec2(p.x, p.y) - c_).squaredNorm() <= r2_) out_->push_back(TagIndex(tag));
    return true;
  }

 private:
  Vec2 c_;
  double r2_;
  std::vector<int>* out_;
};
}  // namespace

RayHit PhysicsWorld::CastRay(const Vec2& from, const Vec2& to, double z, int exclude_robot) const {
  ClosestRay cb(impl_->obstacle_top, impl_->obstacle_bottom, z, exclude_robot);
  b2Vec2 p1(static_cast<float>(from.x()), static_cast<float>(from.y()));
  b2Vec2 p2(static_cast<float>(to.x()), static_cast<float>(to.y()));
  if (b2DistanceSquared(p1, p2) <= 0) return {};
  for (Impl::Region& region : impl_->regions) region.world->RayCast(&cb, p1, p2);
  if (cb.hit.Hit()) cb.hit.distance = (to - from).norm() * cb.fraction_;
  return cb.hit;
}

namespace {
/// A circle round the shape where b2Fixture::RayCast sees it (the body's current transform):
/// a circle is its own; a polygon's is centred on its centroid through its farthest vertex
/// (2.4.1's polygon ray cast ignores the skin radius). Tight, so CastRay's nearest-first
/// scan stops early: the box round a foot-bot would be 41% wider than the foot-bot.
void BoundingCircle(const b2Fixture& f, double* cx, double* cy, double* r) {
  const b2Transform& xf = f.GetBody()->GetTransform();
  const b2Shape* shape = f.GetShape();
  if (shape->GetType() == b2Shape::e_circle) {
    const auto* circle = static_cast<const b2CircleShape*>(shape);
    const b2Vec2 c = b2Mul(xf, circle->m_p);
    *cx = c.x;
    *cy = c.y;
    *r = circle->m_radius;
    return;
  }
  const auto* poly = static_cast<const b2PolygonShape*>(shape);
  double r2 = 0;
  for (int i = 0; i < poly->m_count; ++i) {
    const double dx = static_cast<double>(poly->m_vertices[i].x) - poly->m_centroid.x;
    const double dy = static_cast<double>(poly->m_vertices[i].y) - poly->m_centroid.y;
    r2 = std::max(r2, dx * dx + dy * dy);
  }
  const b2Vec2 c = b2Mul(xf, poly->m_centroid);
  *cx = c.x;
  *cy = c.y;
  *r = std::sqrt(r2);
}

// m: far above float rounding at arena scale (Box2D's hit points lie within ~1e-5 m of the
// shape), so no shape a ray touches is ever dropped, nor cut off by CastRay's early stop.
constexpr double kCircleSlack = 1e-3;
}  // namespace

namespace {
/// The bounding circle of every shape (non-finite ones dropped: no ray can hit them
/// either), filed in the ray grid by their boxes.
template <class Impl>
void FileRayCircles(Impl* im) {
  std::vector<ShapeCircle>& circles = im->ray_circles;
  circles.clear();
  for (auto& region : im->regions)
    for (b2Body* b = region.world->GetBodyList(); b; b = b->GetNext()) {
      for (b2Fixture* f = b->GetFixtureList(); f; f = f->GetNext()) {
        const uintptr_t tag = f->GetUserData().pointer;
        const BodyKind kind = TagKind(tag);
        if (kind == BodyKind::None) continue;
        ShapeCircle c;
        BoundingCircle(*f, &c.cx, &c.cy, &c.r);
        c.r += kCircleSlack;
        if (!std::isfinite(c.cx) || !std::isfinite(c.cy) || !std::isfinite(c.r)) continue;
        const int index = TagIndex(tag);
        if (kind != BodyKind::Obstacle) c.robot = index;  // a robot's body or gripper disc
        HeightSpan(kind, index, im->obstacle_top, im->obstacle_bottom, &c.bottom, &c.top);
        c.fixture = f;
        circles.push_back(c);
      }
    }
  const int n = static_cast<int>(circles.size());
  Vec2 lo = Vec2::Zero(), hi = Vec2::Zero();
  if (n > 0) lo = hi = Vec2(circles[0].cx, circles[0].cy);
  for (const ShapeCircle& c : circles) {
    lo = lo.cwiseMin(Vec2(c.cx - c.r, c.cy - c.r));
    hi = hi.cwiseMax(Vec2(c.cx + c.r, c.cy + c.r));
  }
  // A robot flung far away must not make the grid huge: past a few cells per shape, the
  // cells grow instead (queries get slower, never wrong). Room for a foot-bot-sized circle
  // in four cells each.
  im->ray_grid.CoverSpan(lo, hi, kRayCellSize, std::max(4096.0, 4.0 * n));
  im->ray_grid.Reserve(4 * circles.size(), circles.size());
  im->ray_grid.FileBoxes(
      n, [&](int i) { return Vec2(circles[i].cx - circles[i].r, circles[i].cy - circles[i].r); },
      [&](int i) { return Vec2(circles[i].cx + circles[i].r, circles[i].cy + circles[i].r); });
}
}  // namespace

void PhysicsWorld::EnsureRayGrid() const {
  Impl& im = *impl_;
  if (im.grid_built_at.load(std::memory_order_acquire) == im.shapes_moved) return;
  // The first query after a change rebuilds; the others of a parallel stage wait for it.
  std::lock_guard<std::mutex> lock(im.grid_mutex);
  if (im.grid_built_at.load(std::memory_order_relaxed) == im.shapes_moved) return;
  FileRayCircles(&im);
  im.grid_built_at.store(im.shapes_moved, std::memory_order_release);
}

namespace {
/// The gathers' scan: circles filed in the grid cells over the box (x0, y0)-(x1, y1) that span
/// `z` (ReachesHeight's rule), are not robot `exclude_robot`, reach the disc of radius `r` round
/// `center` and pass `keep(dx, dy, circle radius)` (offset from the centre). Each goes into
/// `found` with its `near`; [*lo, *hi] covers those.
template <class Keep>
void Collect(const UniformGrid& grid, const std::vector<ShapeCircle>& circles, double x0, double y0, double x1,
             double y1, const Vec2& center, double r, double z, int exclude_robot, Keep&& keep,
             std::vector<RayCandidate>* found, double* lo, double* hi) {
  grid.ForEachOnceInBox(x0, y0, x1, y1, [&](int i) {
    const ShapeCircle& g = circles[i];
    if (z < g.bottom || z > g.top || (exclude_robot >= 0 && g.robot == exclude_robot)) return;
    const double dx = g.cx - center.x(), dy = g.cy - center.y();
    const double d2 = dx * dx + dy * dy;
    if (d2 > (g.r + r) * (g.r + r) || !keep(dx, dy, g.r)) return;
    const double near = std::sqrt(d2) - g.r;
    *lo = std::min(*lo, near);
    *hi = std::max(*hi, near);
    found->push_back({near, g.cx, g.cy, g.r, g.fixture});
  });
}

/// Whether a circle at offset (dx, dy) from the apex, of radius r, comes within r of the wedge
/// from unit vector u0 counter-clockwise to u1 (less than π on): a point of the wedge lies left
/// of u0 and right of u1, so a circle holding one has its centre within r of both lines.
/// A superset of the circles that meet it.
bool NearWedge(double dx, double dy, double r, const Vec2& u0, const Vec2& u1) {
  return u0.x() * dy - u0.y() * dx >= -r && dx * u1.y() - dy * u1.x() >= -r;
}
}  // namespace

void PhysicsWorld::GatherRayCandidates(const Vec2& center, double radius, double z, int exclude_robot,
                                       RayCandidates* out) const {
  EnsureRayGrid();
  out->scratch.clear();
  const double r = radius + kCircleSlack;
  double lo = 0, hi = 0;  // m, range of `near`
  Collect(
      impl_->ray_grid, impl_->ray_circles, center.x() - r, center.y() - r, center.x() + r, center.y() + r, center, r, z,
      exclude_robot, [](double, double, double) { return true; }, &out->scratch, &lo, &hi);
  out->center = center;
  SortNearestFirst(lo, hi, out);
}

void PhysicsWorld::GatherWedgeCandidates(const Vec2& center, double radius, const Vec2& u0, const Vec2& u1, double z,
                                         int exclude_robot, RayCandidates* out) const {
  EnsureRayGrid();
  out->scratch.clear();
  const double r = radius + kCircleSlack;
  // The sector's bounding box: its apex, the ends of its edges, and its rim where it crosses
  // an axis. The grid files circles by their boxes, so those that meet the sector are in it.
  double x0 = center.x(), y0 = center.y(), x1 = x0, y1 = y0;
  auto cover = [&](const Vec2& u) {
    x0 = std::min(x0, center.x() + r * u.x());
    x1 = std::max(x1, center.x() + r * u.x());
    y0 = std::min(y0, center.y() + r * u.y());
    y1 = std::max(y1, center.y() + r * u.y());
  };
  cover(u0);
  cover(u1);
  for (const Vec2& axis : {Vec2(1, 0), Vec2(0, 1), Vec2(-1, 0), Vec2(0, -1)})
    if (NearWedge(axis.x(), axis.y(), 0, u0, u1)) cover(axis);
  double lo = 0, hi = 0;  // m, range of `near`
  Collect(
      impl_->ray_grid, impl_->ray_circles, x0 - kCircleSlack, y0 - kCircleSlack, x1 + kCircleSlack, y1 + kCircleSlack,
      center, r, z, exclude_robot, [&](double dx, double dy, double cr) { return NearWedge(dx, dy, cr, u0, u1); },
      &out->scratch, &lo, &hi);
  out->center = center;
  SortNearestFirst(lo, hi, out);
}

namespace {
/// m: CastRay's stop is tested against `near` rounded down by one to two of these steps, so a
/// ray tests at most the candidates of two more centimetres; std::sort was 40% of a gather.
constexpr double kNearStep = 0.01;
constexpr int kMaxNearSteps = 1024;
}  // namespace

void PhysicsWorld::SortNearestFirst(double lo, double hi, RayCandidates* out) {
  const std::vector<RayCandidate>& found = out->scratch;
  std::vector<RayCandidate>& items = out->items;
  items.resize(found.size());
  if (found.empty()) return;
  // Counting sort on `near` in steps; each is stored as the floor of the step below its own
  // (a lower bound even if (near - lo) / step rounded up, and non-decreasing along the
  // result). Same order for the same input: deterministic.
  double step = kNearStep;
  while ((hi - lo) / step > kMaxNearSteps) step *= 2;  // a huge obstacle: fewer, coarser steps
  const double inv_step = 1 / step;
  const int steps = static_cast<int>((hi - lo) * inv_step) + 1;
  std::vector<int>& ends = out->bucket_ends;
  ends.reserve(kMaxNearSteps + 2);  // once: later gathers never allocate for it
  auto step_of = [&](double near) { return std::min(static_cast<int>((near - lo) * inv_step), steps - 1); };
  const size_t n = found.size();
  if (n * n < 2 * static_cast<size_t>(steps)) {
    // Few candidates over many steps (a wedge's): a stable insertion sort on the step
    // (`ends` holds the steps placed so far) beats sweeping every step. Same order.
    ends.resize(n);
    for (size_t i = 0; i < n; ++i) {
      const int k = step_of(found[i].near);
      size_t j = i;
      for (; j > 0 && ends[j - 1] > k; --j) {
        ends[j] = ends[j - 1];
        items[j] = items[j - 1];
      }
      ends[j] = k;
      items[j] = found[i];
      items[j].near = lo + std::max(k - 1, 0) * step;
    }
    return;
  }
  ends.resize(steps + 1);
  BucketSort(
      static_cast<int>(n), &ends, [&](int i, auto&& file) { file(step_of(found[i].near)); },
      [&](int slot, int i) {
        items[slot] = found[i];
        items[slot].near = lo + std::max(step_of(found[i].near) - 1, 0) * step;
      });
}

RayHit PhysicsWorld::CastRay(const RayCandidates& candidates, const Vec2& from, const Vec2& to) const {
  // The same float input as CastRay gives b2World::RayCast.
  b2RayCastInput in;
  in.p1.Set(static_cast<float>(from.x()), static_cast<float>(from.y()));
  in.p2.Set(static_cast<float>(to.x()), static_cast<float>(to.y()));
  in.maxFraction = 1;
  if (candidates.items.empty() || b2DistanceSquared(in.p1, in.p2) <= 0) return {};
  const Vec2 d = to - from;
  const double len2 = d.squaredNorm();
  const double len = std::sqrt(len2);
  const double ux = d.x() / len, uy = d.y() / len;
  // Every point of candidate c is at least c.near from the gather centre, hence at least
  // c.near - start from the ray's start: once that exceeds the closest hit so far (or the
  // ray's length), no candidate left can be hit closer. The 1 mm the bounding circles are
  // inflated by keeps this safe against float rounding in Box2D's fractions.
  const double start = (from - candidates.center).norm();
  double reach = len;  // m, how far along the ray a better hit must lie
  float best = 2;
  const b2Fixture* closest = nullptr;
  for (const RayCandidate& c : candidates.items) {
    if (c.near - start > reach) break;
    // Rejects most candidates cheaply, in double: a circle the segment meets has its centre
    // within r of the ray's line, and between r before the start and r past the end.
    const double mx = c.cx - from.x(), my = c.cy - from.y();
    const double across = mx * uy - my * ux;
    if (across * across > c.r * c.r) continue;
    const double along = mx * ux + my * uy;
    if (along < -c.r || along > len + c.r) continue;
    // Box2D's own shape test. The tree's walk passes a clipped maxFraction instead of 1;
    // that only rejects hits no closer than the best so far, so the minimum is the same.
    const auto* f = static_cast<const b2Fixture*>(c.fixture);
    b2RayCastOutput out;
    if (!f->RayCast(&out, in, 0)) continue;
    if (out.fraction < best) {
      best = out.fraction;
      closest = f;
      reach = len * best;
    }
  }
  if (!closest) return {};
  RayHit hit;
  const uintptr_t tag = const_cast<b2Fixture*>(closest)->GetUserData().pointer;  // 2.4.1: no const getter
  hit.kind = TagKind(tag);
  hit.index = TagIndex(tag);
  hit.point = {(1.0f - best) * in.p1.x + best * in.p2.x, (1.0f - best) * in.p1.y + best * in.p2.y};
  hit.distance = (to - from).norm() * best;
  return hit;
}

void PhysicsWorld::RobotsNear(const Vec2& center, double radius, std::vector<int>* out) const {
  out->clear();
  RobotQuery q(center, radius, out);
  b2AABB box;
  box.lowerBound.Set(static_cast<float>(center.x() - radius), static_cast<float>(center.y() - radius));
  box.upperBound.Set(static_cast<float>(center.x() + radius), static_cast<float>(center.y() + radius));
  for (Impl::Region& region : impl_->regions) region.world->QueryAABB(&q, box);
  // The tree's order depends on insertion history, not on indices: sort for determinism.
  std::sort(out->begin(), out->end());
}

}  // namespace essaim
