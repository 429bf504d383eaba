// Lua table of the distance scanner: robot.distance_scanner with the
// actuator's enable(), disable(), set_angle(rad), set_rpm(rpm) (exact argument counts,
// dot-call) and the sensor's short_range / long_range arrays of {angle, distance}.
//
// ARGoS builds both arrays afresh every step. Here the two arrays and their inner tables
// are made once: each tick fills entries 1..n in place from a pool of 12 tables per array
// and sets the rest to nil, so the values a controller reads are the same without a
// table allocation per tick. (Only a reference kept across steps can tell: it sees the
// new readings instead of the old ones; docs/compatibility.md.)
#include <cmath>

#include "devices/commands.h"
#include "lua/robot/lua_devices.h"

namespace essaim {

namespace {
constexpr int kMaxReadings = 12;  // per array: 6 rays × 2 sensors when rotating

int Enable(lua_State* L) {
  if (lua_gettop(L) != 0) return luaL_error(L, "robot.distance_scanner.enable() expects no arguments");
  ScannerEnable(*RobotOf(L));  // at the last requested angle
  return 0;
}

int Disable(lua_State* L) {
  if (lua_gettop(L) != 0) return luaL_error(L, "robot.distance_scanner.disable() expects no arguments");
  ScannerDisable(*RobotOf(L));
  return 0;
}

int SetAngle(lua_State* L) {
  if (lua_gettop(L) != 1) return luaL_error(L, "robot.distance_scanner.set_angle(angle) expects 1 argument");
  const double a = CheckFiniteNumber(L, 1, "robot.distance_scanner.set_angle");
  ScannerSetAngle(*RobotOf(L), a);
  return 0;
}

int SetRpm(lua_State* L) {
  if (lua_gettop(L) != 1) return luaL_error(L, "robot.distance_scanner.set_rpm(rpm) expects 1 argument");
  const double rpm = CheckFiniteNumber(L, 1, "robot.distance_scanner.set_rpm");
  ScannerSetRpm(*RobotOf(L), rpm);
  return 0;
}

/// A new empty array set as scanner[key]; returns its registry ref.
int NewArray(lua_State* L, int scanner, const char* key) {
  lua_createtable(L, kMaxReadings, 0);
  lua_pushvalue(L, -1);
  lua_setfield(L, scanner, key);
  return luaL_ref(L, LUA_REGISTRYINDEX);
}

/// A hidden pool of kMaxReadings {angle, distance} tables; returns its registry ref.
int NewPool(lua_State* L) {
  lua_createtable(L, kMaxReadings, 0);
  for (int i = 1; i <= kMaxReadings; ++i) {
    lua_createtable(L, 0, 2);
    lua_pushnumber(L, 0.0);
    lua_setfield(L, -2, "angle");
    lua_pushnumber(L, 0.0);
    lua_setfield(L, -2, "distance");
    lua_rawseti(L, -2, i);
  }
  return luaL_ref(L, LUA_REGISTRYINDEX);
}

void Fill(lua_State* L, int scanner, LuaKeyRefs* keys, LuaKey key, int array_ref, int pool_ref,
          const ScanReading* readings, int count, int* shown) {
  lua_rawgeti(L, LUA_REGISTRYINDEX, array_ref);
  const int array = lua_gettop(L);
  PushKey(L, keys, key);
  lua_pushvalue(L, array);
  lua_settable(L, scanner);  // put back, should the controller have replaced it
  lua_rawgeti(L, LUA_REGISTRYINDEX, pool_ref);
  const int pool = lua_gettop(L);
  PushKey(L, keys, LuaKey::Angle);
  PushKey(L, keys, LuaKey::Distance);
  const int k_angle = pool + 1, k_distance = pool + 2;
  for (int i = 0; i < count; ++i) {
    lua_rawgeti(L, pool, i + 1);
    RawSetNumber(L, k_angle, readings[i].angle);
    RawSetNumber(L, k_distance, readings[i].distance);
    lua_rawseti(L, array, i + 1);
  }
  ClearStaleTail(L, array, count, shown);
  lua_settop(L, array - 1);
}
}  // namespace

void CreateScannerActuator(lua_State* L, int t, RobotState*) {
  SetFunction(L, t, "enable", Enable);
  SetFunction(L, t, "disable", Disable);
  SetFunction(L, t, "set_angle", SetAngle);
  SetFunction(L, t, "set_rpm", SetRpm);
}

void CreateScannerSensor(lua_State* L, int t, LuaDeviceRefs* refs) {
  t = lua_absindex(L, t);
  // The scanner starts OFF: both arrays empty until it is switched on.
  refs->scanner_short = NewArray(L, t, "short_range");
  refs->scanner_long = NewArray(L, t, "long_range");
  refs->scanner_short_pool = NewPool(L);
  refs->scanner_long_pool = NewPool(L);
  refs->scanner_short_count = refs->scanner_long_count = 0;
}

void PushScanner(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd, LuaDeviceRefs* refs) {
  lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
  const int scanner = lua_gettop(L);
  Fill(L, scanner, keys, LuaKey::ShortRange, refs->scanner_short, refs->scanner_short_pool, rd.scanner_short,
       rd.scanner_short_count, &refs->scanner_short_count);
  Fill(L, scanner, keys, LuaKey::LongRange, refs->scanner_long, refs->scanner_long_pool, rd.scanner_long,
       rd.scanner_long_count, &refs->scanner_long_count);
  lua_pop(L, 1);
}

}  // namespace essaim
