// robot.colored_blob_omnidirectional_camera: enable() / disable() (disabled
// at start) and the blobs [i] = {distance (cm), angle (rad), color = {red, green, blue}}.
// Blob tables are fresh every step, as in ARGoS; colour components are Lua integers.
#include "lua/robot/lua_devices.h"

namespace essaim {

namespace {
int Enable(lua_State* L) {
  RobotOf(L)->camera_enabled = true;
  return 0;
}

int Disable(lua_State* L) {
  RobotOf(L)->camera_enabled = false;
  return 0;
}
}  // namespace

void CreateCameraSensor(lua_State* L, int t, RobotState*) {
  SetFunction(L, t, "enable", Enable);
  SetFunction(L, t, "disable", Disable);
}

void PushCamera(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd, int* count) {
  lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
  const int t = lua_gettop(L);
  const int n = static_cast<int>(rd.blobs.size());
  // Keys pushed once per call, in the order of the stack slots named below.
  if (n > 0)
    for (LuaKey k : {LuaKey::Distance, LuaKey::Angle, LuaKey::Color, LuaKey::Red, LuaKey::Green, LuaKey::Blue})
      PushKey(L, keys, k);
  const int k_distance = t + 1, k_angle = t + 2, k_color = t + 3, k_red = t + 4, k_green = t + 5, k_blue = t + 6;
  for (int i = 0; i < n; ++i) {
    const Blob& b = rd.blobs[static_cast<size_t>(i)];
    lua_createtable(L, 0, 3);
    RawSetNumber(L, k_distance, b.distance);
    RawSetNumber(L, k_angle, b.angle);
    lua_pushvalue(L, k_color);
    lua_createtable(L, 0, 3);
    RawSetInteger(L, k_red, b.color.r);
    RawSetInteger(L, k_green, b.color.g);
    RawSetInteger(L, k_blue, b.color.b);
    lua_rawset(L, -3);
    lua_rawseti(L, t, i + 1);
  }
  ClearStaleTail(L, t, n, count);
  lua_settop(L, t - 1);
}

}  // namespace essaim
