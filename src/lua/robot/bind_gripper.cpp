// robot.gripper: lock_positive() / lock_negative() / unlock() set the
// aperture (+pi/2, -pi/2, 0) applied in the next Act. Arguments are ignored, as ARGoS.
#include "devices/commands.h"
#include "lua/robot/lua_devices.h"

namespace essaim {

namespace {
int LockPositive(lua_State* L) {
  SetGripperAperture(*RobotOf(L), kPi / 2);
  return 0;
}
int LockNegative(lua_State* L) {
  SetGripperAperture(*RobotOf(L), -kPi / 2);
  return 0;
}
int Unlock(lua_State* L) {
  SetGripperAperture(*RobotOf(L), 0);
  return 0;
}
}  // namespace

void CreateGripperActuator(lua_State* L, int t, RobotState*) {
  SetFunction(L, t, "lock_positive", LockPositive);
  SetFunction(L, t, "lock_negative", LockNegative);
  SetFunction(L, t, "unlock", Unlock);
}

}  // namespace essaim
