// Lua tables of the foot-bot devices: created once per robot, refreshed in place every
// tick. One Create/Push pair per device family in lua/robot/bind_*.cpp; lua_devices.cpp holds
// the Lua layer's row of each device (its create and push functions), indexed by
// DeviceType as model/device_table.h's rows.
#pragma once
#include <lua.hpp>

#include "devices/robot_state.h"
#include "lua/robot/lua_device_refs.h"
#include "model/model.h"

namespace essaim {

/// With the `robot` table at the top of the stack, adds every device table of the
/// controller (actuators then sensors, alphabetical, as ARGoS).
void CreateDeviceTables(lua_State* L, const ControllerDef& c, const RobotDef& def, RobotState* robot,
                        LuaDeviceRefs* refs);
/// Copies the readings of every sensor into the tables.
void PushDeviceReadings(lua_State* L, const ControllerDef& c, const RobotState& robot, LuaDeviceRefs* refs);

/// Pushes `key`'s string (interned and given its reference at its first use).
void PushKey(lua_State* L, LuaKeyRefs* keys, LuaKey key);
/// t[key] = v as lua_setfield sets it (a __newindex is honoured), the key from `keys`.
void SetNumberField(lua_State* L, int t, LuaKeyRefs* keys, LuaKey key, double v);

/// Gets (creating if needed, with `array_slots` preallocated) robot[key] as a table, leaves
/// it on the stack, returns a ref.
int DeviceTable(lua_State* L, int robot_index, const char* key, int* ref, int array_slots = 0);
/// robot.<device>[i].value = values[i] for i in 1..n, in place: the inner tables persist
/// (controllers keep references to them); an entry a controller replaced by a non-table is
/// left alone. Raw sets.
void PushValuesInPlace(lua_State* L, int ref, LuaKeyRefs* keys, const double* values, int n);
/// With the table at the top of the stack: t[key] = v, where `key` is a stack index
/// holding the key string (pushed once per call instead of interned per field).
void RawSetNumber(lua_State* L, int key, double v);
void RawSetInteger(lua_State* L, int key, lua_Integer v);
/// Sets array[count+1 .. *shown] to nil (entries left from a longer previous reading) and
/// records `count` as the new length.
void ClearStaleTail(lua_State* L, int array, int count, int* shown);
/// The robot a controller's state drives, kept in the state's extra space (Lua copies it
/// into every coroutine): the bindings are light C functions that find it there, not a
/// closure per robot and function (each an allocation in every state).
void SetStateRobot(lua_State* L, RobotState* robot);
RobotState* RobotOf(lua_State* L);
/// Puts binding `f` (it reads RobotOf) into the table at `t`.
void SetFunction(lua_State* L, int t, const char* name, lua_CFunction f);
/// luaL_checknumber for actuators: NaN or ±inf is a Lua error naming `fn`, the argument
/// and the value (a non-finite command would poison the physics).
double CheckFiniteNumber(lua_State* L, int arg, const char* fn);
/// Clamps of finite but absurd commands (docs/compatibility.md).

// ---- device families (lua/robot/bind_*.cpp)
void CreateWheelsActuator(lua_State* L, int t, RobotState* robot);
void CreateWheelsSensor(lua_State* L, int t);
void PushWheels(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd);
void PushPositioning(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd);
void PushBattery(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd);
// 24 {value, angle} tables (proximity, light): created once, values refreshed in place
void CreateRingSensor(lua_State* L, int t);
void PushRingSensor(lua_State* L, int ref, LuaKeyRefs* keys, const double* values);
void CreateProximitySensor(lua_State* L, int t);
void PushProximity(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd);
void CreateLightSensor(lua_State* L, int t);
void PushLight(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd);
// {value, offset = vector2 (cm)} tables (base_ground 8, motor_ground 4)
void CreateBaseGroundSensor(lua_State* L, int t);
void CreateMotorGroundSensor(lua_State* L, int t);
void PushBaseGround(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd);
void PushMotorGround(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd);
// distance scanner: enable/disable/set_angle/set_rpm; short_range/long_range arrays
void CreateScannerActuator(lua_State* L, int t, RobotState* robot);
void CreateScannerSensor(lua_State* L, int t, LuaDeviceRefs* refs);
void PushScanner(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd, LuaDeviceRefs* refs);
// gripper (lock_positive/lock_negative/unlock) and turret (set_* and rotation)
void CreateGripperActuator(lua_State* L, int t, RobotState* robot);
void CreateTurretActuator(lua_State* L, int t, RobotState* robot);
void CreateTurretSensor(lua_State* L, int t);
void PushTurret(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd);
// range and bearing (set_data/clear_data, messages), LEDs, colored-blob camera
void CreateRabActuator(lua_State* L, int t, RobotState* robot);
void PushRab(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd, int* count);
void CreateLedsActuator(lua_State* L, int t, RobotState* robot);
void CreateCameraSensor(lua_State* L, int t, RobotState* robot);
void PushCamera(lua_State* L, int ref, LuaKeyRefs* keys, const Readings& rd, int* count);

}  // namespace essaim
