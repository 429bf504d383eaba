// Foot-bot gripper actuator. The controller's lock_positive / lock_negative / unlock set an
// aperture; here, in Act, the lock goes to the physics, which grips and lets go inside the
// physics step as ARGoS's dynamics2d does: a locked gripper holding nothing grips what its
// disc touches with a damped spring, an unlocked one lets go at its disc's next contact
// (physics/physics_grip.cpp; docs/compatibility.md, "Gripper and turret").
#include <cmath>

#include "devices/devices.h"

namespace essaim {

void ActGripper(RobotState& robot, PhysicsWorld& physics) {
  robot.gripper_aperture = robot.cmd.gripper_aperture;
  // ARGoS: lock state = |aperture| / (pi/2), locked above one half; Lua only offers
  // +-pi/2 and 0, so this is "aperture != 0".
  physics.SetGripperLocked(robot.index, std::fabs(robot.gripper_aperture) / (kPi / 2) > 0.5);
}

}  // namespace essaim
