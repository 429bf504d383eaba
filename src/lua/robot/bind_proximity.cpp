// Lua tables of the proximity sensor and the ring layout it shares with the
// light sensor: robot.<key>[1..24] = {value, angle}. The 24 inner tables are made
// once with their constant angle; each tick only `value` is rewritten in place, so
// controllers may keep references to them (ARGoS does the same).
#include "devices/devices.h"
#include "lua/robot/lua_devices.h"

namespace essaim {

void CreateRingSensor(lua_State* L, int t) {
  t = lua_absindex(L, t);
  // The keys pushed once (lua_setfield would look each up in the string cache, 48 times).
  lua_pushliteral(L, "value");
  lua_pushliteral(L, "angle");
  const int value = lua_gettop(L) - 1, angle = value + 1;
  for (int k = 0; k < kRingSensorCount; ++k) {
    lua_createtable(L, 0, 2);
    lua_pushvalue(L, value);
    lua_pushnumber(L, 0.0);
    lua_rawset(L, -3);
    lua_pushvalue(L, angle);
    lua_pushnumber(L, RingSensorAngle(k));
    lua_rawset(L, -3);
    lua_rawseti(L, t, k + 1);
  }
  lua_pop(L, 2);
}

void PushRingSensor(lua_State* L, int ref, LuaKeyRefs* keys, const double* values) {
  PushValuesInPlace(L, ref, keys, values, kRingSensorCount);
}

void CreateProximitySensor(lua_State* L, int t) { CreateRingSensor(L, t); }
void PushProximity(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd) {
  PushRingSensor(L, ref, keys, rd.proximity);
}

}  // namespace essaim
