// PhysicsWorld's bodies and fixtures: the regions' worlds, robots (body, gripper disc, wheel
// servo), obstacles (a long static box tiled for rays), poses. The step is physics_step.cpp,
// rays and neighbour queries physics_rays.cpp, the gripper physics_grip.cpp, several regions
// physics_regions_sync.cpp; the constants that make it ARGoS's are argos_dynamics.h.
#include "physics/physics_world.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>

#include "model/physics_regions.h"
#include "physics/argos_dynamics.h"
#include "physics/physics_world_impl.h"

namespace essaim {

namespace {
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
  impl_->disc_shelf = std::make_unique<b2World>(b2Vec2(0, 0));

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
  impl_->free_servos.reserve(model.robots.size());
  impl_->discs.reserve(model.robots.size());
  for (const ObstacleDef& o : model.obstacles) AddObstacle(o);

  for (size_t i = 0; i < model.robots.size(); ++i) AddRobotBody(model.robots[i], static_cast<int>(i));
}

void PhysicsWorld::AddRobotBody(const RobotDef& r, int i) {
  b2World& w = *impl_->regions[RegionOf(impl_->region_defs, {r.pose.x, r.pose.y}, 0)].world;
  b2BodyDef bd;
  bd.type = b2_dynamicBody;
  bd.position.Set(static_cast<float>(r.pose.x), static_cast<float>(r.pose.y));
  bd.angle = static_cast<float>(dyn2d::StartYaw(r.pose.yaw));
  bd.allowSleep = dyn2d::kAllowSleep;
  b2Body* body = w.CreateBody(&bd);
  b2CircleShape circle;
  circle.m_radius = static_cast<float>(footbot::kRadius);
  b2FixtureDef fd;
  fd.shape = &circle;
  fd.friction = dyn2d::ContactFriction(dyn2d::kRobotFriction);
  fd.restitution = dyn2d::kRestitution;
  fd.density = static_cast<float>(dyn2d::kRobotMass / (kPi * footbot::kRadius * footbot::kRadius));
  fd.userData.pointer = PackTag(BodyKind::Robot, i);
  body->CreateFixture(&fd);
  b2MassData md;
  md.mass = static_cast<float>(dyn2d::kRobotMass);
  md.center.SetZero();
  md.I = static_cast<float>(dyn2d::kRobotMoment);
  body->SetMassData(&md);
  impl_->discs.push_back(MakeGripperDisc(impl_->disc_shelf.get(), body, i));

  // The servo: a kinematic body moving at the commanded velocity, tied to the robot by
  // a friction joint, which drives their relative velocity to zero with capped force
  // and torque (argos_dynamics.h, "the wheels' servo").
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
  Impl::FreeServo servo;
  servo.max_force = jd.maxForce;
  servo.max_torque = jd.maxTorque;
  servo.inv_mass = 1.0f / body->GetMass();
  servo.inv_moment = 1.0f / body->GetInertia();
  impl_->free_servos.push_back(servo);
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
  impl_->free_servos.pop_back();
  impl_->discs.back()->GetWorld()->DestroyBody(impl_->discs.back());
  impl_->discs.pop_back();
  impl_->grips.pop_back();
  if (RegionCount() > 1) impl_->robot_ghosts.pop_back();
  ++impl_->shapes_moved;
}

int PhysicsWorld::RegionCount() const { return impl_->RegionCount(); }

int PhysicsWorld::RobotRegion(int robot) const { return impl_->RegionOfBody(AsBody(robots_[robot])); }

namespace {
/// A long static wall's bounding box overlaps most of the tree and makes every ray cast
/// visit it (measured: 1.67 µs per ray with four 32 m walls, 0.46 µs split). Tiled into
/// pieces of at most dyn2d::kMaxStaticPiece, same body and tag: same hits, same distances. At
/// most dyn2d::kMaxStaticPieces pieces: a 1 km square would be a million fixtures. Neighbouring
/// pieces overlap by dyn2d::kSeamOverlap: their float vertices, rounded apart, left gaps of ~6e-8 m
/// that a ray along a seam went through into the wall (the outer faces do not move).
void TileStaticBox(const ObstacleDef& o, b2Body* body, b2FixtureDef* fd, b2PolygonShape* poly) {
  double piece = dyn2d::kMaxStaticPiece;
  while (std::ceil(o.size_x / piece) * std::ceil(o.size_y / piece) > dyn2d::kMaxStaticPieces) piece *= 2;
  const int nx = static_cast<int>(std::ceil(o.size_x / piece));
  const int ny = static_cast<int>(std::ceil(o.size_y / piece));
  // Piece k of n along a side of length `size`: its [lo, hi], inner ends widened.
  auto span = [](double size, int n, int k, double* lo, double* hi) {
    *lo = -size / 2 + size * k / n - (k > 0 ? dyn2d::kSeamOverlap : 0);
    *hi = -size / 2 + size * (k + 1) / n + (k + 1 < n ? dyn2d::kSeamOverlap : 0);
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
    // Boxes collide at their true faces, as ARGoS's do (a static box's pieces too:
    // TileStaticBox copies this shape), movable or not (argos_dynamics.h).
    poly.m_radius = dyn2d::kPolygonSkin;
    fd.shape = &poly;
    area = o.size_x * o.size_y;
  } else {
    circle.m_radius = static_cast<float>(o.radius);
    fd.shape = &circle;
    area = kPi * o.radius * o.radius;
  }
  fd.friction = dyn2d::ContactFriction(o.movable ? dyn2d::kMovableFriction : dyn2d::kStaticFriction);
  fd.restitution = dyn2d::kRestitution;
  fd.density = o.movable ? static_cast<float>(o.mass / area) : 0.0f;
  fd.userData.pointer = PackTag(BodyKind::Obstacle, index);
  if (o.kind == ShapeKind::Box && !o.movable && std::max(o.size_x, o.size_y) > dyn2d::kMaxStaticPiece)
    AddLongStaticBox(o, body, &fd, &poly);
  else
    body->CreateFixture(&fd);
}

/// A movable obstacle's mass (ARGoS's cylinder moment) and its floor friction: a drag
/// towards zero velocity with capped force and torque.
void MakeMovable(const ObstacleDef& o, const PhysicsDef& phys, b2World* world, b2Body* ground, b2Body* body) {
  if (o.kind == ShapeKind::Cylinder) {
    b2MassData md;
    md.mass = static_cast<float>(o.mass);
    md.center.SetZero();
    md.I = static_cast<float>(dyn2d::CylinderMoment(o.mass, o.radius));
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
  const float yaw = static_cast<float>(dyn2d::StartYaw(pose.yaw));  // as AddRobot
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
    const GripTarget& t = impl_->grips[robot].target;
    if (t.kind == BodyKind::Robot) SyncGripperDisc(impl_.get(), held, t.index);
  }
  SyncGripperDisc(impl_.get(), b, robot);
}

Pose2 PhysicsWorld::ObstaclePose(int obstacle) const {
  const b2Body* b = AsBody(obstacles_[obstacle]);
  return {b->GetPosition().x, b->GetPosition().y, b->GetAngle()};
}

void PhysicsWorld::FreezeRobot(int robot) { SetWheelSpeeds(robot, 0, 0); }

}  // namespace essaim
