#include "lua/robot/lua_devices.h"

#include <cmath>

namespace essaim {

RobotState* UpvalueRobot(lua_State* L) { return static_cast<RobotState*>(lua_touserdata(L, lua_upvalueindex(1))); }

double CheckFiniteNumber(lua_State* L, int arg, const char* fn) {
  const double v = luaL_checknumber(L, arg);
  if (!std::isfinite(v)) {
    const char* value = std::isnan(v) ? "nan" : v > 0 ? "inf" : "-inf";
    luaL_error(L, "%s: argument #%d is %s (actuator values must be finite numbers)", fn, arg, value);
  }
  return v;
}

void SetClosure(lua_State* L, int t, const char* name, lua_CFunction f, RobotState* robot) {
  t = lua_absindex(L, t);
  lua_pushlightuserdata(L, robot);
  lua_pushcclosure(L, f, 1);
  lua_setfield(L, t, name);
}

void PushValuesInPlace(lua_State* L, int ref, const double* values, int n) {
  lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
  const int t = lua_gettop(L);
  lua_pushliteral(L, "value");
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

int DeviceTable(lua_State* L, int robot_index, const char* key, int* ref) {
  robot_index = lua_absindex(L, robot_index);
  if (lua_getfield(L, robot_index, key) != LUA_TTABLE) {
    lua_pop(L, 1);
    lua_newtable(L);
    lua_pushvalue(L, -1);
    lua_setfield(L, robot_index, key);
  }
  if (*ref < 0) {
    lua_pushvalue(L, -1);
    *ref = luaL_ref(L, LUA_REGISTRYINDEX);
  }
  return lua_gettop(L);
}

void CreateDeviceTables(lua_State* L, const ControllerDef& c, const RobotDef&, RobotState* robot,
                        LuaDeviceRefs* refs) {
  int robot_t = lua_gettop(L);
  for (const DeviceConfig& d : c.actuators) {
    switch (d.type) {
      case DeviceType::WheelsActuator:
        CreateWheelsActuator(L, DeviceTable(L, robot_t, "wheels", &refs->wheels), robot);
        break;
      case DeviceType::ScannerActuator:
        CreateScannerActuator(L, DeviceTable(L, robot_t, "distance_scanner", &refs->scanner), robot);
        break;
      case DeviceType::GripperActuator:
        CreateGripperActuator(L, DeviceTable(L, robot_t, "gripper", &refs->gripper), robot);
        break;
      case DeviceType::TurretActuator:
        CreateTurretActuator(L, DeviceTable(L, robot_t, "turret", &refs->turret), robot);
        break;
      case DeviceType::LedsActuator:
        CreateLedsActuator(L, DeviceTable(L, robot_t, "leds", &refs->leds), robot);
        break;
      case DeviceType::RabActuator:
        CreateRabActuator(L, DeviceTable(L, robot_t, "range_and_bearing", &refs->rab), robot);
        break;
      default: break;
    }
    lua_settop(L, robot_t);
  }
  for (const DeviceConfig& d : c.sensors) {
    switch (d.type) {
      case DeviceType::WheelsSensor: CreateWheelsSensor(L, DeviceTable(L, robot_t, "wheels", &refs->wheels)); break;
      case DeviceType::PositioningSensor: DeviceTable(L, robot_t, "positioning", &refs->positioning); break;
      case DeviceType::BatterySensor: DeviceTable(L, robot_t, "battery", &refs->battery); break;
      case DeviceType::ProximitySensor:
        CreateProximitySensor(L, DeviceTable(L, robot_t, "proximity", &refs->proximity));
        break;
      case DeviceType::LightSensor: CreateLightSensor(L, DeviceTable(L, robot_t, "light", &refs->light)); break;
      case DeviceType::BaseGroundSensor:
        CreateBaseGroundSensor(L, DeviceTable(L, robot_t, "base_ground", &refs->base_ground));
        break;
      case DeviceType::MotorGroundSensor:
        CreateMotorGroundSensor(L, DeviceTable(L, robot_t, "motor_ground", &refs->motor_ground));
        break;
      case DeviceType::ScannerSensor:
        CreateScannerSensor(L, DeviceTable(L, robot_t, "distance_scanner", &refs->scanner), refs);
        break;
      case DeviceType::TurretEncoderSensor: CreateTurretSensor(L, DeviceTable(L, robot_t, "turret", &refs->turret)); break;
      case DeviceType::RabSensor: DeviceTable(L, robot_t, "range_and_bearing", &refs->rab); break;
      case DeviceType::CameraSensor:
        CreateCameraSensor(L, DeviceTable(L, robot_t, "colored_blob_omnidirectional_camera", &refs->camera), robot);
        break;
      default: break;
    }
    lua_settop(L, robot_t);
  }
}

void PushDeviceReadings(lua_State* L, const ControllerDef& c, const RobotState& robot, LuaDeviceRefs* refs) {
  const Readings& rd = robot.rd;
  for (const DeviceConfig& d : c.sensors) {
    switch (d.type) {
      case DeviceType::WheelsSensor: PushWheels(L, refs->wheels, rd); break;
      case DeviceType::PositioningSensor: PushPositioning(L, refs->positioning, rd); break;
      case DeviceType::BatterySensor: PushBattery(L, refs->battery, rd); break;
      case DeviceType::ProximitySensor: PushProximity(L, refs->proximity, rd); break;
      case DeviceType::LightSensor: PushLight(L, refs->light, rd); break;
      case DeviceType::BaseGroundSensor: PushBaseGround(L, refs->base_ground, rd); break;
      case DeviceType::MotorGroundSensor: PushMotorGround(L, refs->motor_ground, rd); break;
      case DeviceType::ScannerSensor: PushScanner(L, rd, refs); break;
      case DeviceType::TurretEncoderSensor: PushTurret(L, refs->turret, rd); break;
      case DeviceType::RabSensor: PushRab(L, refs->rab, rd, &refs->rab_count); break;
      case DeviceType::CameraSensor: PushCamera(L, refs->camera, rd, &refs->blob_count); break;
      default: break;
    }
  }
}

}  // namespace essaim
