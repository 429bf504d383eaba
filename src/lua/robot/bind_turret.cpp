// robot.turret: the actuator's set_rotation(rad), set_rotation_speed(x)
// (x·pi/30 rad/s), set_position_control_mode(), set_speed_control_mode(),
// set_passive_mode(); the encoder's rotation (rad, relative to the body). Both devices
// share the table. Commands apply in the next Act (devices/turret.cpp).
#include <algorithm>
#include <cstdio>

#include "devices/commands.h"
#include "lua/robot/lua_devices.h"

namespace essaim {

namespace {
// One number argument, dot-call (colon syntax fails the count, as ARGoS's checks do).
double OneNumber(lua_State* L, const char* fn) {
  if (lua_gettop(L) != 1) luaL_error(L, "robot.turret.%s() expects 1 argument", fn);
  char name[64];
  std::snprintf(name, sizeof name, "robot.turret.%s", fn);
  return CheckFiniteNumber(L, 1, name);
}
int SetRotation(lua_State* L) {
  double a = OneNumber(L, "set_rotation");
  TurretSetRotation(*RobotOf(L), a);
  return 0;
}
int SetRotationSpeed(lua_State* L) {
  double x = OneNumber(L, "set_rotation_speed");
  TurretSetRotationSpeed(*RobotOf(L), x);
  return 0;
}
int SetPositionMode(lua_State* L) {
  TurretSetMode(*RobotOf(L), TurretMode::Position);
  return 0;
}
int SetSpeedMode(lua_State* L) {
  TurretSetMode(*RobotOf(L), TurretMode::Speed);
  return 0;
}
int SetPassiveMode(lua_State* L) {
  TurretSetMode(*RobotOf(L), TurretMode::Passive);
  return 0;
}
}  // namespace

void CreateTurretActuator(lua_State* L, int t, RobotState*) {
  SetFunction(L, t, "set_rotation", SetRotation);
  SetFunction(L, t, "set_rotation_speed", SetRotationSpeed);
  SetFunction(L, t, "set_position_control_mode", SetPositionMode);
  SetFunction(L, t, "set_speed_control_mode", SetSpeedMode);
  SetFunction(L, t, "set_passive_mode", SetPassiveMode);
}

void CreateTurretSensor(lua_State* L, int t) {
  lua_pushnumber(L, 0);
  lua_setfield(L, t, "rotation");
}

void PushTurret(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd) {
  lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
  SetNumberField(L, lua_gettop(L), keys, LuaKey::Rotation, rd.turret_rotation);
  lua_pop(L, 1);
}

}  // namespace essaim
