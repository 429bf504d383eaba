// Foot-bot turret actuator and encoder. The turret is kinematic robot
// state: an angle relative to the body, in [-pi, pi]. ARGoS moves a second physics body
// whose angular velocity it sets once per tick; essaim applies the same per-tick laws to
// the angle directly, so a turret is never back-driven by what it holds:
//   off, passive: the angle stays (ARGoS ties the turret to the body with a gear joint);
//   speed:        the angle advances by speed·dt;
//   position:     ARGoS's PD, w = 0.4·e + 0.2·(e − e_prev)/dt with e the signed-normalized
//                 error to the target and e_prev the previous position-mode error (0 at
//                 start), then angle += w·dt. It converges slowly (about 3 s time
//                 constant), as in ARGoS.
// Act runs after the gripper's (alphabetical tag order) and turns the gripper disc; a held
// object hangs on a spring from the robot's centre, so the turret does not carry it.
#include "devices/devices.h"

namespace essaim {

namespace {
constexpr double kTurretP = 0.4;  // 1/s
constexpr double kTurretD = 0.2;  // dimensionless (multiplies a per-tick error change / dt)
}  // namespace

void ActTurret(RobotState& robot, PhysicsWorld& physics, double dt) {
  robot.turret_mode = robot.cmd.turret_mode;
  double w = 0;  // rad/s relative to the body
  switch (robot.turret_mode) {
    case TurretMode::Position: {
      double e = WrapSigned(robot.cmd.turret_rotation - robot.turret_rotation);
      w = kTurretP * e + kTurretD * (e - robot.turret_previous_error) / dt;
      robot.turret_previous_error = e;
      break;
    }
    case TurretMode::Speed:
      w = robot.cmd.turret_speed;
      break;
    case TurretMode::Off:
    case TurretMode::Passive:
      break;
  }
  if (w == 0) return;
  robot.turret_rotation = WrapSigned(robot.turret_rotation + w * dt);
  physics.SetGripTurret(robot.index, robot.turret_rotation);
}

void SenseTurretEncoder(RobotState& robot) { robot.rd.turret_rotation = robot.turret_rotation; }

}  // namespace essaim
