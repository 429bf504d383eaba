// PhysicsWorld's step: the wheels' servo, the sub-steps of a tick (each region's, with the
// grips' springs) and the sub-step shift that puts Box2D's contacts where Chipmunk's are.
#include <box2d/box2d.h>

#include <cmath>

#include "physics/argos_dynamics.h"
#include "physics/physics_world.h"
#include "physics/physics_world_impl.h"

namespace essaim {

void PhysicsWorld::SetWheelSpeeds(int robot, double left, double right) {
  b2Body* body = AsBody(robots_[robot]);
  b2Body* control = impl_->controls[robot];
  Impl::FreeServo& servo = impl_->free_servos[robot];
  servo.v = b2Vec2(0, 0);
  servo.w = 0;
  if (left != 0 || right != 0) {
    double a = body->GetAngle();
    double v = (left + right) / 2;
    double w = (right - left) / footbot::kAxisLength;
    servo.v = b2Vec2(static_cast<float>(v * std::cos(a)), static_cast<float>(v * std::sin(a)));
    servo.w = static_cast<float>(w);
  }
  control->SetLinearVelocity(servo.v);
  control->SetAngularVelocity(servo.w);
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
  b2World& w = *impl_->regions[region].world;
  const bool grips = !impl_->grip_robots.empty();
  // Several regions step at once and migrate servos with their robots: Box2D solves all.
  const bool free_servos = impl_->RegionCount() == 1;
  for (int i = first; i < first + count; ++i) {
    if (grips) {
      if (i > 0) GripEvents(region, i);  // sub-step 0's were taken for every region at once
      ApplyGripSprings(region, i, h);
    }
    if (free_servos) SolveFreeServos(impl_.get(), robots_, i == 0, h);
    w.Step(h, dyn2d::kVelocityIterations, dyn2d::kPositionIterations);
    if (free_servos) NoteStep(impl_.get(), h);
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

// The sub-step shift (argos_dynamics.h, "the step"): a tick shifts the bodies ahead by
// kShiftSubsteps sub-steps along their velocity, steps, and shifts them back.
void PhysicsWorld::ShiftDynamicBodies(float h) {
  for (size_t i = 0; i < robots_.size(); ++i) {
    Impl::FreeServo& s = impl_->free_servos[i];
    if (s.dormant)
      WakeDormant(AsBody(robots_[i]), &s, h);  // the tick's end: its pose shifted back
    else
      ShiftAlongVelocity(robots_[i], h);
  }
  for (void* body : obstacles_) ShiftAlongVelocity(body, h);
}

void PhysicsWorld::Step(double dt, int substeps, const PhysicsRunner& runner) {
  const float h = static_cast<float>(dt / substeps);
  const float shift = dyn2d::kShiftSubsteps * h;
  ShiftDynamicBodies(shift);
  BeginGripTick(substeps);
  if (impl_->RegionCount() == 1)
    StepRegion(0, 0, substeps, h);
  else
    StepRegions(dt, substeps, runner);
  EndGripTick();
  ShiftDynamicBodies(-shift);
  SyncGripperDiscs(impl_.get(), robots_);
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
}  // namespace essaim
