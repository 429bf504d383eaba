// robot.leds: set_all_colors(colour) and set_single_color(i, colour), where
// colour is a name ("red"), a string "r,g,b,a" or three numbers r, g, b (alpha 255).
// A bad colour or index is a Lua error naming it. Colours apply in the next Act stage.
#include <cstdio>

#include "core/color.h"
#include "lua/robot/bind_byte.h"
#include "lua/robot/lua_devices.h"

namespace essaim {

namespace {
// Kept out of the bindings: std::string must not be alive where luaL_error longjmps.
bool ColorFromText(const char* text, Color* out) {
  std::optional<Color> c = ParseColor(text);
  if (!c) return false;
  *out = *c;
  return true;
}

/// Reads the colour at stack slots first.. (1 string or 3 numbers); errors name `fn`.
Color CheckColor(lua_State* L, int first, const char* fn) {
  const int n = lua_gettop(L) - first + 1;
  Color c;
  if (n == 1) {
    if (lua_type(L, first) != LUA_TSTRING)
      luaL_error(L, "robot.leds.%s: the colour must be a string (a name or \"r,g,b,a\") or three numbers", fn);
    const char* text = lua_tostring(L, first);
    if (!ColorFromText(text, &c))
      luaL_error(L,
                 "robot.leds.%s: unknown colour '%s' (a name such as \"red\", or \"r,g,b,a\" with four 0..255 values)",
                 fn, text);
    return c;
  }
  char name[48];
  std::snprintf(name, sizeof name, "robot.leds.%s", fn);
  c.r = LuaNumberToByte(CheckFiniteNumber(L, first, name));
  c.g = LuaNumberToByte(CheckFiniteNumber(L, first + 1, name));
  c.b = LuaNumberToByte(CheckFiniteNumber(L, first + 2, name));
  c.a = 255;
  return c;
}

int SetAllColors(lua_State* L) {
  const int n = lua_gettop(L);
  if (n != 1 && n != 3) return luaL_error(L, "robot.leds.set_all_colors() expects either one or three arguments");
  Color c = CheckColor(L, 1, "set_all_colors()");
  RobotState* r = RobotOf(L);
  for (Color& led : r->cmd.leds) led = c;
  return 0;
}

int SetSingleColor(lua_State* L) {
  const int n = lua_gettop(L);
  if (n != 2 && n != 4) return luaL_error(L, "robot.leds.set_single_color() expects either two or four arguments");
  double idx = CheckFiniteNumber(L, 1, "robot.leds.set_single_color()");
  if (!(idx >= 1 && idx < footbot::kLedCount + 1))
    return luaL_error(L, "robot.leds.set_single_color(): LED index %f out of range 1..%d", idx, footbot::kLedCount);
  Color c = CheckColor(L, 2, "set_single_color()");
  RobotOf(L)->cmd.leds[static_cast<int>(idx) - 1] = c;
  return 0;
}
}  // namespace

void CreateLedsActuator(lua_State* L, int t, RobotState*) {
  SetFunction(L, t, "set_all_colors", SetAllColors);
  SetFunction(L, t, "set_single_color", SetSingleColor);
}

}  // namespace essaim
