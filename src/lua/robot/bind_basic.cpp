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

void PushWheels(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd) {
  lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
  const int t = lua_gettop(L);
  SetNumberField(L, t, keys, LuaKey::VelocityLeft, rd.velocity_left);
  SetNumberField(L, t, keys, LuaKey::VelocityRight, rd.velocity_right);
  SetNumberField(L, t, keys, LuaKey::DistanceLeft, rd.distance_left);
  SetNumberField(L, t, keys, LuaKey::DistanceRight, rd.distance_right);
  lua_pop(L, 1);
}

void PushPositioning(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd) {
  // Fresh values each step: controllers keep last step's position to compare with.
  lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
  const int t = lua_gettop(L);
  PushKey(L, keys, LuaKey::Position);
  PushVector3(L, rd.position.x(), rd.position.y(), rd.position.z());
  lua_settable(L, t);
  PushKey(L, keys, LuaKey::Orientation);
  PushQuaternion(L, rd.quat_w, rd.quat_x, rd.quat_y, rd.quat_z);
  lua_settable(L, t);
  lua_pop(L, 1);
}

void PushBattery(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd) {
  lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
  const int t = lua_gettop(L);
  SetNumberField(L, t, keys, LuaKey::AvailableCharge, rd.battery_charge);
  SetNumberField(L, t, keys, LuaKey::TimeLeft, rd.battery_time_left);
  lua_pop(L, 1);
}

}  // namespace essaim
