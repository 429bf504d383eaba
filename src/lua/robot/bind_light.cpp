// Lua table of the light sensor: robot.light[1..24] = {value, angle}, the
// proximity ring's layout (lua/robot/bind_proximity.cpp).
#include "lua/robot/lua_devices.h"

namespace essaim {

void CreateLightSensor(lua_State* L, int t) { CreateRingSensor(L, t); }
void PushLight(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd) { PushRingSensor(L, ref, keys, rd.light); }

}  // namespace essaim
