// Foot-bot gripper actuator. The controller's lock_positive /
// lock_negative / unlock set an aperture; here, in Act, a locked gripper holding nothing
// grips whatever grippable shape touches its disc (the physics joint does the holding),
// and an unlocked one lets go. ARGoS grips on contact during the physics step; essaim
// decides once per tick, from the positions at the end of the previous tick
// (docs/compatibility.md, "Gripper and turret").
#include <cmath>

#include "devices/devices.h"

namespace essaim {

void ActGripper(RobotState& robot, PhysicsWorld& physics) {
  robot.gripper_aperture = robot.cmd.gripper_aperture;
  // ARGoS: lock state = |aperture| / (pi/2), locked above one half; Lua only offers
  // +-pi/2 and 0, so this is "aperture != 0".
  const bool locked = std::fabs(robot.gripper_aperture) / (kPi / 2) > 0.5;
  if (locked)
    physics.TryGrip(robot.index, robot.turret_rotation);  // no-op while holding
  else
    physics.Release(robot.index);
}

}  // namespace essaim
