// The one table of foot-bot devices, one row per DeviceType: XML element, Lua table and
// what it holds, accepted attributes, what its cost grows with. `essaim devices` prints it,
// the loader reads it as the schema of <sensors> and <actuators>. The layers above keep
// their own rows, indexed by the same enum and checked complete at compile time:
// devices/device_functions.cpp (init, act, sense) and lua/robot/lua_devices.cpp (create, push).
// docs/adding-a-device.md walks through adding one.
#pragma once
#include <array>
#include <string>

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
constexpr int kDeviceCount = static_cast<int>(DeviceType::Count);

/// What a device's work per tick grows with, beside the number of robots carrying it.
enum class DeviceCost {
  Fixed,          // a few arithmetic operations (wheels, positioning, battery, LEDs...)
  PerRay,         // ray casts against the shapes near the robot (proximity, light, scanner)
  PerFloorPoint,  // floor raster look-ups (ground sensors)
  PerJoint,       // Box2D joints made or moved in the one physics world (gripper, turret)
  PerPartner,     // robots within range (range-and-bearing)
  PerLed,         // LEDs within view (camera)
};

struct DeviceAttr {
  const char* name;
  const char* default_value;  // "" = none / required when `required`
  const char* doc;
  bool required = false;
};

/// A row's attributes: a view of a constant array.
struct DeviceAttrs {
  const DeviceAttr* items = nullptr;
  int count = 0;
  constexpr const DeviceAttr* begin() const { return items; }
  constexpr const DeviceAttr* end() const { return items + count; }
};
template <int N>
constexpr DeviceAttrs AttrsOf(const DeviceAttr (&items)[N]) {
  return {items, N};
}

struct DeviceRow {
  DeviceType type;
  const char* xml_name;  // tag inside <sensors> / <actuators>
  bool is_sensor;
  const char* lua_key;          // robot.<lua_key>
  const char* implementations;  // accepted `implementation` values, comma-separated
  bool supported;               // false: recognised ARGoS device not implemented yet
  DeviceCost cost;
  const char* doc;  // what robot.<lua_key> holds or offers
  DeviceAttrs attrs;
};

// `inline`: one definition in the program, so every unit's kDeviceRows points at the same arrays.
namespace device_attrs {
inline constexpr DeviceAttr kNoise = {"noise_level", "0", "uniform noise amplitude added to each value"};
inline constexpr DeviceAttr kShowRays = {"show_rays", "false", "accepted for compatibility; essaim is headless"};
inline constexpr DeviceAttr kWheelsActuator[] = {{"bias_avg", "0", "per-robot wheel speed bias mean (m/s), drawn once"},
                                                 {"bias_stddev", "0", "per-robot wheel speed bias std-dev (m/s)"},
                                                 {"factor_avg", "1", "per-command multiplicative noise mean"},
                                                 {"factor_stddev", "0", "per-command multiplicative noise std-dev"},
                                                 {"bias_avg_left", "", "left-wheel override"},
                                                 {"bias_avg_right", "", "right-wheel override"},
                                                 {"bias_stddev_left", "", "left-wheel override"},
                                                 {"bias_stddev_right", "", "right-wheel override"},
                                                 {"factor_avg_left", "", "left-wheel override"},
                                                 {"factor_avg_right", "", "right-wheel override"},
                                                 {"factor_stddev_left", "", "left-wheel override"},
                                                 {"factor_stddev_right", "", "right-wheel override"}};
inline constexpr DeviceAttr kLeds[] = {{"medium", "", "id of the <led> medium", true}};
inline constexpr DeviceAttr kWheelsSensor[] = {{"vel_noise_range", "0:0", "uniform noise on velocities (cm/s)"},
                                               {"dist_noise_range", "0:0", "uniform noise on distances (cm)"}};
inline constexpr DeviceAttr kPositioning[] = {
    {"pos_noise_range", "0:0", "uniform noise per axis (m)"},
    {"angle_noise_range", "0:0", "uniform noise on the rotation angle (rad, as ARGoS parses it)"},
    {"axis_noise_range", "0:0", "uniform noise per rotation-axis component"}};
inline constexpr DeviceAttr kRing[] = {kShowRays, kNoise};
inline constexpr DeviceAttr kGround[] = {kNoise};
inline constexpr DeviceAttr kRabSensor[] = {{"medium", "", "id of the <range_and_bearing> medium", true},
                                            kShowRays,
                                            {"noise_std_dev", "0", "std-dev of the position noise (m)"},
                                            {"packet_drop_prob", "0", "probability of dropping each packet"}};
inline constexpr DeviceAttr kScanner[] = {kShowRays, {"noise_range", "0:0", "parsed and ignored, as ARGoS"}};
inline constexpr DeviceAttr kCamera[] = {{"medium", "", "id of the <led> medium", true},
                                         kShowRays,
                                         {"noise_std_dev", "0", "relative noise on the blob vector"}};
inline constexpr DeviceAttr kBattery[] = {{"noise_range", "0:0", "uniform noise on the charge"}};
}  // namespace device_attrs

/// Indexed by DeviceType: kDeviceRows[int(type)].type == type (checked below).
inline constexpr std::array<DeviceRow, kDeviceCount> kDeviceRows = {{
    // ---- actuators
    {DeviceType::WheelsActuator, "differential_steering", false, "wheels", "default", true, DeviceCost::Fixed,
     "robot.wheels.set_velocity(left, right) in cm/s", AttrsOf(device_attrs::kWheelsActuator)},
    {DeviceType::LedsActuator, "leds", false, "leds", "default", true, DeviceCost::Fixed,
     "robot.leds.set_all_colors / set_single_color (13 LEDs)", AttrsOf(device_attrs::kLeds)},
    {DeviceType::RabActuator,
     "range_and_bearing",
     false,
     "range_and_bearing",
     "default",
     true,
     DeviceCost::Fixed,
     "robot.range_and_bearing.set_data / clear_data",
     {}},
    {DeviceType::ScannerActuator,
     "footbot_distance_scanner",
     false,
     "distance_scanner",
     "default",
     true,
     DeviceCost::Fixed,
     "robot.distance_scanner.enable / disable / set_angle / set_rpm",
     {}},
    {DeviceType::GripperActuator,
     "footbot_gripper",
     false,
     "gripper",
     "default",
     true,
     DeviceCost::PerJoint,
     "robot.gripper.lock_positive / lock_negative / unlock",
     {}},
    {DeviceType::TurretActuator,
     "footbot_turret",
     false,
     "turret",
     "default",
     true,
     DeviceCost::PerJoint,
     "robot.turret.set_rotation / set_rotation_speed / set_*_mode",
     {}},
    // ---- sensors
    {DeviceType::WheelsSensor, "differential_steering", true, "wheels", "default", true, DeviceCost::Fixed,
     "robot.wheels.velocity_left/right (cm/s), distance_left/right (cm), axis_length (cm)",
     AttrsOf(device_attrs::kWheelsSensor)},
    {DeviceType::PositioningSensor, "positioning", true, "positioning", "default", true, DeviceCost::Fixed,
     "robot.positioning.position (vector3, m), orientation (quaternion)", AttrsOf(device_attrs::kPositioning)},
    {DeviceType::ProximitySensor, "footbot_proximity", true, "proximity", "default", true, DeviceCost::PerRay,
     "robot.proximity[1..24] = {value, angle}", AttrsOf(device_attrs::kRing)},
    {DeviceType::LightSensor, "footbot_light", true, "light", "rot_z_only", true, DeviceCost::PerRay,
     "robot.light[1..24] = {value, angle}", AttrsOf(device_attrs::kRing)},
    {DeviceType::BaseGroundSensor, "footbot_base_ground", true, "base_ground", "rot_z_only", true,
     DeviceCost::PerFloorPoint, "robot.base_ground[1..8] = {value (0/1), offset}", AttrsOf(device_attrs::kGround)},
    {DeviceType::MotorGroundSensor, "footbot_motor_ground", true, "motor_ground", "rot_z_only", true,
     DeviceCost::PerFloorPoint, "robot.motor_ground[1..4] = {value, offset}", AttrsOf(device_attrs::kGround)},
    {DeviceType::RabSensor, "range_and_bearing", true, "range_and_bearing", "medium", true, DeviceCost::PerPartner,
     "robot.range_and_bearing[i] = {range, horizontal_bearing, vertical_bearing, data}",
     AttrsOf(device_attrs::kRabSensor)},
    {DeviceType::ScannerSensor, "footbot_distance_scanner", true, "distance_scanner", "rot_z_only", true,
     DeviceCost::PerRay, "robot.distance_scanner.short_range / long_range = {angle, distance}",
     AttrsOf(device_attrs::kScanner)},
    {DeviceType::CameraSensor, "colored_blob_omnidirectional_camera", true, "colored_blob_omnidirectional_camera",
     "rot_z_only", true, DeviceCost::PerLed, "blobs {distance, angle, color={red,green,blue}}; enable() / disable()",
     AttrsOf(device_attrs::kCamera)},
    {DeviceType::BatterySensor, "battery", true, "battery", "default", true, DeviceCost::Fixed,
     "robot.battery.available_charge (0..1), time_left (s)", AttrsOf(device_attrs::kBattery)},
    {DeviceType::TurretEncoderSensor,
     "footbot_turret_encoder",
     true,
     "turret",
     "default",
     true,
     DeviceCost::Fixed,
     "robot.turret.rotation (rad)",
     {}},
}};

/// Every row present, in enum order, with its names filled in. A missing row would be a
/// value-initialised one (type 0, null names): this fails the build instead.
constexpr bool DeviceRowsComplete() {
  for (int i = 0; i < kDeviceCount; ++i) {
    const DeviceRow& row = kDeviceRows[i];
    if (static_cast<int>(row.type) != i || !row.xml_name || !row.lua_key || !row.implementations || !row.doc)
      return false;
  }
  return true;
}
static_assert(DeviceRowsComplete(), "kDeviceRows: one complete row per DeviceType, in enum order");

constexpr const DeviceRow& GetDeviceRow(DeviceType type) { return kDeviceRows[static_cast<int>(type)]; }
constexpr bool IsSensor(DeviceType type) { return GetDeviceRow(type).is_sensor; }
/// "per ray", "per partner"...: the cost class as `essaim devices` prints it.
const char* CostName(DeviceCost cost);
/// Row for an XML tag in <sensors> (is_sensor) or <actuators>; nullptr if unknown.
const DeviceRow* FindDevice(const std::string& xml_name, bool is_sensor);

}  // namespace essaim
