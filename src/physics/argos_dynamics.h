// Every constant that makes essaim's Box2D dynamics ARGoS's dynamics2d (Chipmunk 6.0.2), in
// one place, each with where it comes from: ARGoS's source (ilpincy/argos3 @ 421bd763, paths
// under src/plugins/simulator/physics_engines/dynamics2d/ unless said), the spec
// (/work/shared/argos-spec.md §N) or the trajectories ARGoS printed (/work/shared/motion,
// README "What the comparison showed", causes 1-4, and "Box pushes"). The foot-bot's geometry,
// masses and default force caps are model data (model/model.h, namespace footbot); the floor
// drag of movable obstacles and the gripping rigidity are the model's PhysicsDef defaults.
// Physics-only: included by src/physics/*.cpp alone.
#pragma once
#include "core/math.h"
#include "model/model.h"

namespace essaim {
namespace dyn2d {

// ---- contacts -----------------------------------------------------------------------------

/// Shapes' friction coefficients (spec §11.2, §11.3; dynamics2d_footbot_model.cpp,
/// dynamics2d_box_model.cpp, dynamics2d_cylinder_model.cpp): foot-bot 0.7, static box or
/// cylinder 0.1, movable box or cylinder 0.7.
constexpr double kRobotFriction = 0.7;
constexpr double kStaticFriction = 0.1;
constexpr double kMovableFriction = 0.7;
/// Elasticity of every shape (same sources): no bounce.
constexpr float kRestitution = 0;

/// The friction a fixture holds for ARGoS's coefficient `argos`. Chipmunk multiplies the two
/// shapes' coefficients (foot-bot on wall 0.7 × 0.1 = 0.07), Box2D takes the square root of
/// the product of the two fixtures' (b2MixFriction): fixtures holding the squares give
/// Chipmunk's product in every pair, every region, at no cost per contact. Motion README,
/// cause 1: without it a robot slid along a wall 8.1 mm a tick against ARGoS's 13.2 mm.
inline float ContactFriction(double argos) { return static_cast<float>(argos * argos); }

/// Box2D wraps polygons in a skin of b2_polygonRadius (1 cm) that collides but that rays do not
/// see; ARGoS's polygons have none (motion README, cause 4: robots stopped 7.7-10 mm before a
/// box's face where ARGoS's touch it). Every box drops it. Static ones (and a long wall's
/// pieces): a robot placed within 5 mm of one was pushed off it at the first step, where ARGoS
/// leaves it. Movable ones (README "Box pushes"): a pushed box ran 1 cm ahead of ARGoS's from
/// the first contact and stopped 1 cm short of a wall (48 scenes: boxes a median 10.2 mm off,
/// 0.18 mm without it). Two boxes then touch only once they overlap, as Chipmunk's do; Box2D's
/// solver stops their approach and its position pass keeps the overlap under its 5 mm slop
/// (tests/physics/argos_box_test.cpp).
constexpr float kPolygonSkin = 0;

// ---- masses and moments -------------------------------------------------------------------

/// kg under the wheels' force: ARGoS's 1.6 kg base plus its 0.08 kg gripper body pinned to the
/// base's centre (spec §1.2; motion README, cause 2: with 1.6 kg the first tick at 10 cm/s moved
/// 9.94 mm against ARGoS's 8.89 mm).
constexpr double kRobotMass = footbot::kMass;

/// kg·m², the foot-bot's moment about its centre. Quirk 1 (spec §1.2,
/// dynamics2d_footbot_model.cpp): cpMomentForCircle(m, 0, 2r) takes the diameter as radius,
/// I = m (2r)² / 2; base and gripper bodies turn together (a gear joint) and each has the
/// base's mass's moment, so the robot's is twice that.
constexpr double kRobotMoment = 2 * footbot::kBaseMass * (2 * footbot::kRadius) * (2 * footbot::kRadius) / 2;

/// kg·m², a movable cylinder's moment: the same quirk 1 (spec §11.3,
/// dynamics2d_cylinder_model.cpp), 4x a uniform disc's. A movable box's moment is Chipmunk's
/// cpMomentForBox, m (w² + h²) / 12: the same as Box2D's from the box's density.
inline double CylinderMoment(double mass, double radius) { return mass * (2 * radius) * (2 * radius) / 2; }

// ---- the wheels' servo and the floor ------------------------------------------------------

// The wheels drive a kinematic body tied to the robot by a friction joint with capped force
// and torque: Chipmunk's pivot + gear joints with maxBias 0 to ARGoS's massless control body
// (spec §11.2, dynamics2d_velocity_control.cpp), caps footbot::kMaxForce (15 N) and
// footbot::kMaxTorque (150 N·m) unless the XML says otherwise. The heading of a tick's command
// is the body's at the tick's start (the same source: computed once per tick). Both wheels at
// exactly 0: the servo stands still and the robot brakes. Movable obstacles drag on the floor
// the same way, towards zero velocity, with PhysicsDef's caps (1.49 N, 1.49 N·m; spec §11.3),
// not scaled by mass.

/// ARGoS never lets bodies sleep (spec §11.1: "no sleeping"); a sleeping robot would also stop
/// following its servo.
constexpr bool kAllowSleep = false;

/// The start yaw a body takes: ARGoS turns the XML's yaw into a quaternion and back (-π..π)
/// before its body takes it (CEmbodiedEntity's orientation, read by the dynamics2d models), so a
/// robot placed at 300° starts at -60° and its orientation quaternion says so. The body's angle
/// then accumulates unwrapped, as Chipmunk's does (spec §11.2, written-back orientation).
inline double StartYaw(double yaw) { return WrapSigned(yaw); }

// ---- the step -----------------------------------------------------------------------------

// Sub-steps per tick: PhysicsDef::iterations, ARGoS's `iterations` (default 10, spec §11.1).
//
// The sub-step shift (PhysicsWorld::Step): Chipmunk moves each body at the start of a sub-step
// with the velocity the sub-step before solved, then solves velocities; Box2D solves, then
// moves. Box2D's pose after a sub-step is therefore Chipmunk's after the next one's move, and the
// two engines meet the same contacts at the same places when Box2D's bodies are one sub-step
// ahead along their velocity. Between ticks the bodies hold ARGoS's poses, which everything
// else reads. Motion README, cause 3: without it every change of wheel speed took effect one
// sub-step early (a robot stopping after 30 ticks at 10 cm/s ended 9 µm short of ARGoS's 0.3 m,
// a spin in place 0.00714 rad apart).
constexpr int kShiftSubsteps = 1;

/// Box2D's solver passes per sub-step. Not ARGoS's (Chipmunk runs `iterations` passes of its
/// own solver): 4 velocity and 2 position iterations with 10 sub-steps are 40 passes a tick, and
/// 8/3 cost 9 % more instructions with no change in any motion or fidelity test.
constexpr int kVelocityIterations = 4;
constexpr int kPositionIterations = 2;

// ---- the gripper (physics_grip.cpp) -------------------------------------------------------

/// N·s/m: ARGoS's GRIPPING_SPRING_DAMPING (dynamics2d_gripping.cpp); the spring's stiffness is
/// PhysicsDef::gripping_rigidity (ARGoS's gripping_rigidity attribute, default 10000).
constexpr double kGripDamping = 0.99;

// Not emulated: Chipmunk's collision slop of 0.1 m (spec §11.1, quirk 3), under which ARGoS
// leaves overlaps up to 10 cm; Box2D pushes overlaps apart past its own 5 mm
// (docs/compatibility.md, "Collision slop").

// ---- essaim's own, keeping ARGoS's results with Box2D -------------------------------------

/// m, longest side of one piece of a long static box (TileStaticBox): a long wall's box covers
/// most of Box2D's tree and every ray visited it (1.67 µs per ray with four 32 m walls, 0.46 µs
/// tiled). At most kMaxStaticPieces pieces per box (longer pieces beyond).
constexpr double kMaxStaticPiece = 1.0;
constexpr double kMaxStaticPieces = 4096;
/// m, how far neighbouring pieces of a tiled wall overlap: far above their float rounding
/// (~6e-8 m at arena scale, gaps that a ray along a seam went through), far below anything a
/// sensor resolves.
constexpr double kSeamOverlap = 1e-5;

}  // namespace dyn2d
}  // namespace essaim
