// Lua tables of the ground sensors: robot.base_ground[1..8] and
// robot.motor_ground[1..4] = {value, offset}, offset a vector2 in cm set once, value
// rewritten in place each tick (0 until the first sense, so init() sees 0).
#include "devices/devices.h"
#include "lua/robot/lua_devices.h"
#include "lua/robot/lua_math_types.h"

namespace essaim {

namespace {
template <int N>
void Create(lua_State* L, int t, const double (&offsets)[N][2]) {
  t = lua_absindex(L, t);
  for (int i = 0; i < N; ++i) {
    lua_createtable(L, 0, 2);
    lua_pushnumber(L, 0.0);
    lua_setfield(L, -2, "value");
    PushVector2(L, offsets[i][0], offsets[i][1]);
    lua_setfield(L, -2, "offset");
    lua_rawseti(L, t, i + 1);
  }
}

}  // namespace

void CreateBaseGroundSensor(lua_State* L, int t) { Create(L, t, kBaseGroundOffsets); }
void CreateMotorGroundSensor(lua_State* L, int t) { Create(L, t, kMotorGroundOffsets); }
void PushBaseGround(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd) {
  PushValuesInPlace(L, ref, keys, rd.base_ground, kBaseGroundCount);
}
void PushMotorGround(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd) {
  PushValuesInPlace(L, ref, keys, rd.motor_ground, kMotorGroundCount);
}

}  // namespace essaim
