#include "lua/robot/lua_devices.h"

#include <array>
#include <cmath>
#include <cstring>

#include "devices/devices.h"

namespace essaim {

void SetStateRobot(lua_State* L, RobotState* robot) { *static_cast<RobotState**>(lua_getextraspace(L)) = robot; }

RobotState* RobotOf(lua_State* L) { return *static_cast<RobotState**>(lua_getextraspace(L)); }

double CheckFiniteNumber(lua_State* L, int arg, const char* fn) {
  const double v = luaL_checknumber(L, arg);
  if (!std::isfinite(v)) {
    const char* value = std::isnan(v) ? "nan" : v > 0 ? "inf" : "-inf";
    luaL_error(L, "%s: argument #%d is %s (actuator values must be finite numbers)", fn, arg, value);
  }
  return v;
}

void SetFunction(lua_State* L, int t, const char* name, lua_CFunction f) {
  t = lua_absindex(L, t);
  lua_pushcfunction(L, f);
  lua_setfield(L, t, name);
}

namespace {
// LuaKey's strings, indexed by the enum.
constexpr const char* kKeyNames[] = {"",
                                     "value",
                                     "position",
                                     "orientation",
                                     "velocity_left",
                                     "velocity_right",
                                     "distance_left",
                                     "distance_right",
                                     "available_charge",
                                     "time_left",
                                     "rotation",
                                     "range",
                                     "horizontal_bearing",
                                     "vertical_bearing",
                                     "data",
                                     "distance",
                                     "angle",
                                     "color",
                                     "red",
                                     "green",
                                     "blue",
                                     "short_range",
                                     "long_range"};
static_assert(std::size(kKeyNames) == kLuaKeyCount + 1, "lua_devices.cpp: one name per LuaKey, in enum order");
}  // namespace

void PushKey(lua_State* L, LuaKeyRefs* keys, LuaKey key) {
  int& ref = keys->ref[static_cast<int>(key)];
  if (ref >= 0) {
    lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
    return;
  }
  lua_pushstring(L, kKeyNames[static_cast<int>(key)]);  // first use in this state: interned once, kept
  lua_pushvalue(L, -1);
  ref = luaL_ref(L, LUA_REGISTRYINDEX);
}

void SetNumberField(lua_State* L, int t, LuaKeyRefs* keys, LuaKey key, double v) {
  PushKey(L, keys, key);
  lua_pushnumber(L, v);
  lua_settable(L, t);
}

void PushValuesInPlace(lua_State* L, int ref, LuaKeyRefs* keys, const double* values, int n) {
  lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
  const int t = lua_gettop(L);
  PushKey(L, keys, LuaKey::Value);
  const int key = t + 1;
  for (int i = 0; i < n; ++i) {
    if (lua_rawgeti(L, t, i + 1) == LUA_TTABLE) RawSetNumber(L, key, values[i]);
    lua_pop(L, 1);
  }
  lua_settop(L, t - 1);
}

void RawSetNumber(lua_State* L, int key, double v) {
  lua_pushvalue(L, key);
  lua_pushnumber(L, v);
  lua_rawset(L, -3);
}

void RawSetInteger(lua_State* L, int key, lua_Integer v) {
  lua_pushvalue(L, key);
  lua_pushinteger(L, v);
  lua_rawset(L, -3);
}

void ClearStaleTail(lua_State* L, int array, int count, int* shown) {
  for (int i = count; i < *shown; ++i) {
    lua_pushnil(L);
    lua_rawseti(L, array, i + 1);
  }
  *shown = count;
}

int DeviceTable(lua_State* L, int robot_index, const char* key, int* ref, int array_slots) {
  robot_index = lua_absindex(L, robot_index);
  if (lua_getfield(L, robot_index, key) != LUA_TTABLE) {
    lua_pop(L, 1);
    lua_createtable(L, array_slots, 0);
    lua_pushvalue(L, -1);
    lua_setfield(L, robot_index, key);
  }
  if (*ref < 0) {
    lua_pushvalue(L, -1);
    *ref = luaL_ref(L, LUA_REGISTRYINDEX);
  }
  return lua_gettop(L);
}

namespace {
// The Lua layer's row of a device: what its table holds beside the readings (closures,
// fixed fields, arrays made once), and how a reading is copied in. nullptr: nothing.
using CreateFn = void (*)(lua_State* L, int table, RobotState* robot, LuaDeviceRefs* refs);
using PushFn = void (*)(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd, LuaDeviceRefs* refs);
struct LuaDeviceRow {
  DeviceType type;
  CreateFn create;
  PushFn push;  // sensors only
};

using T = DeviceType;
// Each entry adapts a binding (lua_devices.h) to the row's signature.
constexpr std::array<LuaDeviceRow, kDeviceCount> kRows = {{
    // ---- actuators
    {T::WheelsActuator, [](lua_State* L, int t, RobotState* r, LuaDeviceRefs*) { CreateWheelsActuator(L, t, r); },
     nullptr},
    {T::LedsActuator, [](lua_State* L, int t, RobotState* r, LuaDeviceRefs*) { CreateLedsActuator(L, t, r); }, nullptr},
    {T::RabActuator, [](lua_State* L, int t, RobotState* r, LuaDeviceRefs*) { CreateRabActuator(L, t, r); }, nullptr},
    {T::ScannerActuator, [](lua_State* L, int t, RobotState* r, LuaDeviceRefs*) { CreateScannerActuator(L, t, r); },
     nullptr},
    {T::GripperActuator, [](lua_State* L, int t, RobotState* r, LuaDeviceRefs*) { CreateGripperActuator(L, t, r); },
     nullptr},
    {T::TurretActuator, [](lua_State* L, int t, RobotState* r, LuaDeviceRefs*) { CreateTurretActuator(L, t, r); },
     nullptr},
    // ---- sensors
    {T::WheelsSensor, [](lua_State* L, int t, RobotState*, LuaDeviceRefs*) { CreateWheelsSensor(L, t); },
     [](lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd, LuaDeviceRefs*) { PushWheels(L, ref, keys, rd); }},
    {T::PositioningSensor, nullptr,
     [](lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd, LuaDeviceRefs*) {
       PushPositioning(L, ref, keys, rd);
     }},
    {T::ProximitySensor, [](lua_State* L, int t, RobotState*, LuaDeviceRefs*) { CreateProximitySensor(L, t); },
     [](lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd, LuaDeviceRefs*) {
       PushProximity(L, ref, keys, rd);
     }},
    {T::LightSensor, [](lua_State* L, int t, RobotState*, LuaDeviceRefs*) { CreateLightSensor(L, t); },
     [](lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd, LuaDeviceRefs*) { PushLight(L, ref, keys, rd); }},
    {T::BaseGroundSensor, [](lua_State* L, int t, RobotState*, LuaDeviceRefs*) { CreateBaseGroundSensor(L, t); },
     [](lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd, LuaDeviceRefs*) {
       PushBaseGround(L, ref, keys, rd);
     }},
    {T::MotorGroundSensor, [](lua_State* L, int t, RobotState*, LuaDeviceRefs*) { CreateMotorGroundSensor(L, t); },
     [](lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd, LuaDeviceRefs*) {
       PushMotorGround(L, ref, keys, rd);
     }},
    {T::RabSensor, nullptr,
     [](lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd, LuaDeviceRefs* refs) {
       PushRab(L, ref, keys, rd, &refs->rab_count);
     }},
    {T::ScannerSensor, [](lua_State* L, int t, RobotState*, LuaDeviceRefs* refs) { CreateScannerSensor(L, t, refs); },
     [](lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd, LuaDeviceRefs* refs) {
       PushScanner(L, ref, keys, rd, refs);
     }},
    {T::CameraSensor, [](lua_State* L, int t, RobotState* r, LuaDeviceRefs*) { CreateCameraSensor(L, t, r); },
     [](lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd, LuaDeviceRefs* refs) {
       PushCamera(L, ref, keys, rd, &refs->blob_count);
     }},
    {T::BatterySensor, nullptr,
     [](lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd,
        LuaDeviceRefs*) { PushBattery(L, ref, keys, rd); }},
    {T::TurretEncoderSensor, [](lua_State* L, int t, RobotState*, LuaDeviceRefs*) { CreateTurretSensor(L, t); },
     [](lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd, LuaDeviceRefs*) { PushTurret(L, ref, keys, rd); }},
}};

// Every DeviceType has its row, in enum order; every sensor pushes its readings.
constexpr bool RowsComplete() {
  for (int i = 0; i < kDeviceCount; ++i) {
    if (static_cast<int>(kRows[i].type) != i) return false;
    if (kDeviceRows[i].is_sensor != (kRows[i].push != nullptr)) return false;
  }
  return true;
}
static_assert(RowsComplete(), "lua_devices.cpp: one row per DeviceType, in enum order, a push function per sensor");

// The reference of a table this robot already has under the same key (an actuator's and a
// sensor's wheels, turret...), or -1.
int SharedRef(const LuaDeviceRefs& refs, DeviceType type) {
  const char* key = GetDeviceRow(type).lua_key;
  for (int i = 0; i < kDeviceCount; ++i)
    if (refs.table[i] >= 0 && std::strcmp(kDeviceRows[i].lua_key, key) == 0) return refs.table[i];
  return -1;
}

// The readings array a device's table holds from the start (its Create fills it): sized
// at once, not grown one reading at a time.
int ArraySlots(DeviceType type) {
  switch (type) {
    case T::ProximitySensor:
    case T::LightSensor:
      return kRingSensorCount;
    case T::BaseGroundSensor:
      return kBaseGroundCount;
    case T::MotorGroundSensor:
      return kMotorGroundCount;
    default:
      return 0;
  }
}

void CreateTables(lua_State* L, int robot_t, const std::vector<DeviceConfig>& devices, RobotState* robot,
                  LuaDeviceRefs* refs) {
  for (const DeviceConfig& d : devices) {
    int& ref = refs->table[static_cast<int>(d.type)];
    ref = SharedRef(*refs, d.type);
    const int t = DeviceTable(L, robot_t, GetDeviceRow(d.type).lua_key, &ref, ArraySlots(d.type));
    if (CreateFn create = kRows[static_cast<int>(d.type)].create) create(L, t, robot, refs);
    lua_settop(L, robot_t);
  }
}
}  // namespace

void CreateDeviceTables(lua_State* L, const ControllerDef& c, const RobotDef&, RobotState* robot, LuaDeviceRefs* refs) {
  const int robot_t = lua_gettop(L);
  CreateTables(L, robot_t, c.actuators, robot, refs);
  CreateTables(L, robot_t, c.sensors, robot, refs);
}

void PushDeviceReadings(lua_State* L, const ControllerDef& c, const RobotState& robot, LuaDeviceRefs* refs) {
  for (const DeviceConfig& d : c.sensors) {
    const int i = static_cast<int>(d.type);
    kRows[i].push(L, refs->table[i], &refs->keys, robot.rd, refs);
  }
}

}  // namespace essaim
