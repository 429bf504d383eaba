// Lua tables of the differential-steering wheels, positioning and battery.
#include <algorithm>
#include <cmath>

#include "devices/commands.h"
#include "lua/robot/lua_devices.h"
#include "lua/robot/lua_math_types.h"

namespace essaim {

namespace {
int SetVelocity(lua_State* L) {
  // Dot-call with exactly two numbers, cm/s (colon syntax fails the count, as ARGoS).
  if (lua_gettop(L) != 2) return luaL_error(L, "robot.wheels.set_velocity(left, right) expects 2 arguments");
  RobotState* r = RobotOf(L);
  const char* fn = "robot.wheels.set_velocity";
  const double left = CheckFiniteNumber(L, 1, fn);
  SetWheelVelocity(*r, left, CheckFiniteNumber(L, 2, fn));
  return 0;
}

void SetNumber(lua_State* L, int t, const char* k, double v) {
  lua_pushnumber(L, v);
  lua_setfield(L, t, k);
}
}  // namespace

void CreateWheelsActuator(lua_State* L, int t, RobotState*) { SetFunction(L, t, "set_velocity", SetVelocity); }

void CreateWheelsSensor(lua_State* L, int t) {
  SetNumber(L, t, "axis_length", 14.0);  // cm; 0.14 * 100 is not exactly 14 in binary
  for (const char* k : {"velocity_left", "velocity_right", "distance_left", "distance_right"}) SetNumber(L, t, k, 0);
}

void PushWheels(lua_State* L, int ref, const Readings& rd) {
  lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
  int t = lua_gettop(L);
  SetNumber(L, t, "velocity_left", rd.velocity_left);
  SetNumber(L, t, "velocity_right", rd.velocity_right);
  SetNumber(L, t, "distance_left", rd.distance_left);
  SetNumber(L, t, "distance_right", rd.distance_right);
  lua_pop(L, 1);
}

void PushPositioning(lua_State* L, int ref, const Readings& rd) {
  // Fresh values each step: controllers keep last step's position to compare with.
  lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
  PushVector3(L, rd.position.x(), rd.position.y(), rd.position.z());
  lua_setfield(L, -2, "position");
  PushQuaternion(L, rd.quat_w, rd.quat_x, rd.quat_y, rd.quat_z);
  lua_setfield(L, -2, "orientation");
  lua_pop(L, 1);
}

void PushBattery(lua_State* L, int ref, const Readings& rd) {
  lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
  int t = lua_gettop(L);
  SetNumber(L, t, "available_charge", rd.battery_charge);
  SetNumber(L, t, "time_left", rd.battery_time_left);
  lua_pop(L, 1);
}

}  // namespace essaim
