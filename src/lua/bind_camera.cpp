// robot.colored_blob_omnidirectional_camera (spec §7.2): enable() / disable() (disabled
// at start) and the blobs [i] = {distance (cm), angle (rad), color = {red, green, blue}}.
// Blob tables are fresh every step, as in ARGoS; colour components are Lua integers.
#include "lua/lua_devices.h"

namespace essaim {

namespace {
int Enable(lua_State* L) {
  UpvalueRobot(L)->camera_enabled = true;
  return 0;
}

int Disable(lua_State* L) {
  UpvalueRobot(L)->camera_enabled = false;
  return 0;
}
}  // namespace

void CreateCameraSensor(lua_State* L, int t, RobotState* robot) {
  SetClosure(L, t, "enable", Enable, robot);
  SetClosure(L, t, "disable", Disable, robot);
}

void PushCamera(lua_State* L, int ref, const Readings& rd, int* count) {
  lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
  const int t = lua_gettop(L);
  const int n = static_cast<int>(rd.blobs.size());
  for (int i = 0; i < n; ++i) {
    const Blob& b = rd.blobs[static_cast<size_t>(i)];
    lua_createtable(L, 0, 3);
    lua_pushnumber(L, b.distance);
    lua_setfield(L, -2, "distance");
    lua_pushnumber(L, b.angle);
    lua_setfield(L, -2, "angle");
    lua_createtable(L, 0, 3);
    lua_pushinteger(L, b.color.r);
    lua_setfield(L, -2, "red");
    lua_pushinteger(L, b.color.g);
    lua_setfield(L, -2, "green");
    lua_pushinteger(L, b.color.b);
    lua_setfield(L, -2, "blue");
    lua_setfield(L, -2, "color");
    lua_rawseti(L, t, i + 1);
  }
  for (int i = n; i < *count; ++i) {
    lua_pushnil(L);
    lua_rawseti(L, t, i + 1);
  }
  *count = n;
  lua_pop(L, 1);
}

}  // namespace essaim
