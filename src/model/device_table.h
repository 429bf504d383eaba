// The one table of foot-bot devices: XML name, kind, Lua key and attributes.
// A new device = one enum value, one row here, one sense/act function in devices/, one
// Lua binding in lua/robot/lua_devices.cpp, one test. `essaim devices` prints this table.
#pragma once
#include <string>
#include <vector>

namespace essaim {

enum class DeviceType {
  // actuators
  WheelsActuator,
  LedsActuator,
  RabActuator,
  ScannerActuator,
  GripperActuator,
  TurretActuator,
  // sensors
  WheelsSensor,
  PositioningSensor,
  ProximitySensor,
  LightSensor,
  BaseGroundSensor,
  MotorGroundSensor,
  RabSensor,
  ScannerSensor,
  CameraSensor,
  BatterySensor,
  TurretEncoderSensor,
  Count
};

struct DeviceAttr {
  const char* name;
  const char* default_value;  // "" = none / required when `required`
  const char* doc;
  bool required = false;
};

struct DeviceRow {
  DeviceType type;
  const char* xml_name;       // tag inside <sensors> / <actuators>
  bool is_sensor;
  const char* lua_key;        // robot.<lua_key>
  const char* implementations;  // accepted `implementation` values, comma-separated
  bool supported;             // false: recognised ARGoS device not implemented yet
  const char* doc;
  std::vector<DeviceAttr> attrs;
};

const std::vector<DeviceRow>& DeviceTable();
const DeviceRow& GetDeviceRow(DeviceType type);
/// Row for an XML tag in <sensors> (is_sensor) or <actuators>; nullptr if unknown.
const DeviceRow* FindDevice(const std::string& xml_name, bool is_sensor);

}  // namespace essaim
