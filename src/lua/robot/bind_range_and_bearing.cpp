// robot.range_and_bearing: set_data / clear_data, and the received messages
// robot.range_and_bearing[i] = {range, horizontal_bearing, vertical_bearing, data}.
// Each message and its data table are fresh every step, as in ARGoS: a controller may
// keep last step's message and compare it with the new one. Bytes are Lua integers.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "lua/robot/bind_byte.h"
#include "lua/robot/lua_devices.h"

namespace essaim {

namespace {
constexpr lua_Integer kOnePassBytes = 256;  // payloads up to this are read once into a stack buffer

/// Beyond this magnitude a number is no byte, even wrapped: ARGoS's cast is undefined there.
constexpr double kMaxByteMagnitude = 2147483648.0;  // 2^31

/// `v` as a byte, wrapping as ARGoS's cast does; a Lua error naming the value when its
/// magnitude is out of range. `what` names the argument.
uint8_t RangedByte(lua_State* L, double v, const char* what) {
  if (std::fabs(v) < kMaxByteMagnitude) return LuaNumberToByte(v);
  char shown[32];
  std::snprintf(shown, sizeof shown, "%g", v);
  luaL_error(L,
             "robot.range_and_bearing.set_data: %s %s is out of range (a byte: numbers within +-2^31 wrap modulo 256)",
             what, shown);
  return 0;
}

/// array[i] as a byte, or a Lua error naming the element. One lua_geti per call: a table
/// with __index sees each element read once per pass, as in ARGoS.
uint8_t ElementByte(lua_State* L, lua_Integer i) {
  if (lua_geti(L, 1, i) != LUA_TNUMBER)
    luaL_error(L, "robot.range_and_bearing.set_data(array): element #%d is not a number", static_cast<int>(i));
  int exact = 0;
  const lua_Integer n = lua_tointegerx(L, -1, &exact);  // bytes are integers: the cheap read
  constexpr lua_Integer kMaxExact = static_cast<lua_Integer>(kMaxByteMagnitude);
  if (exact && n > -kMaxExact && n < kMaxExact) {  // LuaNumberToByte(double(n)), without the double
    lua_pop(L, 1);
    return static_cast<uint8_t>(n);
  }
  const double v = exact ? static_cast<double>(n) : lua_tonumber(L, -1);
  lua_pop(L, 1);
  if (!std::isfinite(v))
    luaL_error(L, "robot.range_and_bearing.set_data(array): element #%d is %s (must be a finite number)",
               static_cast<int>(i),
               std::isnan(v) ? "nan"
               : v > 0       ? "inf"
                             : "-inf");
  char what[48];
  std::snprintf(what, sizeof what, "element #%d", static_cast<int>(i));
  return RangedByte(L, v, what);
}

int SetData(lua_State* L) {
  RobotState* r = RobotOf(L);
  const lua_Integer size = static_cast<lua_Integer>(r->cmd.rab_data.size());
  const int args = lua_gettop(L);
  if (args == 1) {
    luaL_checktype(L, 1, LUA_TTABLE);
    if (static_cast<lua_Integer>(luaL_len(L, 1)) != size)
      return luaL_error(
          L, "robot.range_and_bearing.set_data(array) expects an array of %d numbers (rab_data_size), got %d",
          static_cast<int>(size), static_cast<int>(luaL_len(L, 1)));
    // Every element is checked before the payload changes: a bad one leaves it untouched.
    uint8_t* out = r->cmd.rab_data.data();
    if (size <= kOnePassBytes) {
      uint8_t bytes[kOnePassBytes];
      for (lua_Integer i = 1; i <= size; ++i) bytes[i - 1] = ElementByte(L, i);
      std::copy(bytes, bytes + size, out);
    } else {  // rare big payloads: a checking pass, then a writing pass
      for (lua_Integer i = 1; i <= size; ++i) ElementByte(L, i);
      for (lua_Integer i = 1; i <= size; ++i) out[i - 1] = ElementByte(L, i);
    }
    return 0;
  }
  if (args == 2) {
    double idx = CheckFiniteNumber(L, 1, "robot.range_and_bearing.set_data");
    double value = CheckFiniteNumber(L, 2, "robot.range_and_bearing.set_data");
    if (!(idx >= 1 && idx < static_cast<double>(size) + 1))
      return luaL_error(L, "robot.range_and_bearing.set_data(idx, value) expects idx between 1 and %d, got %f",
                        static_cast<int>(size), idx);
    r->cmd.rab_data[static_cast<size_t>(idx) - 1] = RangedByte(L, value, "value");
    return 0;
  }
  return luaL_error(L, "robot.range_and_bearing.set_data() expects either one or two arguments");
}

int ClearData(lua_State* L) {
  RobotState* r = RobotOf(L);
  std::fill(r->cmd.rab_data.begin(), r->cmd.rab_data.end(), 0);
  return 0;
}
}  // namespace

void CreateRabActuator(lua_State* L, int t, RobotState*) {
  SetFunction(L, t, "set_data", SetData);
  SetFunction(L, t, "clear_data", ClearData);
}

void PushRab(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd, int* count) {
  lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
  const int t = lua_gettop(L);
  const int n = static_cast<int>(rd.rab.size());
  // Keys pushed once per call, in the order of the stack slots named below.
  if (n > 0)
    for (LuaKey k : {LuaKey::Range, LuaKey::HorizontalBearing, LuaKey::VerticalBearing, LuaKey::Data})
      PushKey(L, keys, k);
  const int k_range = t + 1, k_hb = t + 2, k_vb = t + 3, k_data = t + 4;
  for (int i = 0; i < n; ++i) {
    const RabPacket& p = rd.rab[static_cast<size_t>(i)];
    lua_createtable(L, 0, 4);
    RawSetNumber(L, k_range, p.range);
    RawSetNumber(L, k_hb, p.horizontal_bearing);
    RawSetNumber(L, k_vb, p.vertical_bearing);
    lua_pushvalue(L, k_data);
    lua_createtable(L, p.size, 0);
    for (int k = 0; k < p.size; ++k) {
      lua_pushinteger(L, p.data[k]);
      lua_rawseti(L, -2, k + 1);
    }
    lua_rawset(L, -3);
    lua_rawseti(L, t, i + 1);
  }
  ClearStaleTail(L, t, n, count);
  lua_settop(L, t - 1);
}

}  // namespace essaim
