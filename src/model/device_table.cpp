#include "model/device_table.h"

#include <cassert>

namespace essaim {

namespace {
std::vector<DeviceRow> MakeTable() {
  using T = DeviceType;
  const DeviceAttr kNoise = {"noise_level", "0", "uniform noise amplitude added to each value"};
  const DeviceAttr kShowRays = {"show_rays", "false", "accepted for compatibility; essaim is headless"};
  return {
      // ---- actuators
      {T::WheelsActuator, "differential_steering", false, "wheels", "default", true,
       "robot.wheels.set_velocity(left, right) in cm/s",
       {{"bias_avg", "0", "per-robot wheel speed bias mean (m/s), drawn once"},
        {"bias_stddev", "0", "per-robot wheel speed bias std-dev (m/s)"},
        {"factor_avg", "1", "per-command multiplicative noise mean"},
        {"factor_stddev", "0", "per-command multiplicative noise std-dev"},
        {"bias_avg_left", "", "left-wheel override"}, {"bias_avg_right", "", "right-wheel override"},
        {"bias_stddev_left", "", "left-wheel override"}, {"bias_stddev_right", "", "right-wheel override"},
        {"factor_avg_left", "", "left-wheel override"}, {"factor_avg_right", "", "right-wheel override"},
        {"factor_stddev_left", "", "left-wheel override"}, {"factor_stddev_right", "", "right-wheel override"}}},
      {T::LedsActuator, "leds", false, "leds", "default", true,
       "robot.leds.set_all_colors / set_single_color (13 LEDs)",
       {{"medium", "", "id of the <led> medium", true}}},
      {T::RabActuator, "range_and_bearing", false, "range_and_bearing", "default", true,
       "robot.range_and_bearing.set_data / clear_data", {}},
      {T::ScannerActuator, "footbot_distance_scanner", false, "distance_scanner", "default", true,
       "robot.distance_scanner.enable / disable / set_angle / set_rpm", {}},
      {T::GripperActuator, "footbot_gripper", false, "gripper", "default", true,
       "robot.gripper.lock_positive / lock_negative / unlock", {}},
      {T::TurretActuator, "footbot_turret", false, "turret", "default", true,
       "robot.turret.set_rotation / set_rotation_speed / set_*_mode", {}},
      // ---- sensors
      {T::WheelsSensor, "differential_steering", true, "wheels", "default", true,
       "robot.wheels.velocity_left/right (cm/s), distance_left/right (cm), axis_length (cm)",
       {{"vel_noise_range", "0:0", "uniform noise on velocities (cm/s)"},
        {"dist_noise_range", "0:0", "uniform noise on distances (cm)"}}},
      {T::PositioningSensor, "positioning", true, "positioning", "default", true,
       "robot.positioning.position (vector3, m), orientation (quaternion)",
       {{"pos_noise_range", "0:0", "uniform noise per axis (m)"},
        {"angle_noise_range", "0:0", "uniform noise on the rotation angle (rad, as ARGoS parses it)"},
        {"axis_noise_range", "0:0", "uniform noise per rotation-axis component"}}},
      {T::ProximitySensor, "footbot_proximity", true, "proximity", "default", true,
       "robot.proximity[1..24] = {value, angle}", {kShowRays, kNoise}},
      {T::LightSensor, "footbot_light", true, "light", "rot_z_only", true,
       "robot.light[1..24] = {value, angle}", {kShowRays, kNoise}},
      {T::BaseGroundSensor, "footbot_base_ground", true, "base_ground", "rot_z_only", true,
       "robot.base_ground[1..8] = {value (0/1), offset}", {kNoise}},
      {T::MotorGroundSensor, "footbot_motor_ground", true, "motor_ground", "rot_z_only", true,
       "robot.motor_ground[1..4] = {value, offset}", {kNoise}},
      {T::RabSensor, "range_and_bearing", true, "range_and_bearing", "medium", true,
       "robot.range_and_bearing[i] = {range, horizontal_bearing, vertical_bearing, data}",
       {{"medium", "", "id of the <range_and_bearing> medium", true},
        kShowRays,
        {"noise_std_dev", "0", "std-dev of the position noise (m)"},
        {"packet_drop_prob", "0", "probability of dropping each packet"}}},
      {T::ScannerSensor, "footbot_distance_scanner", true, "distance_scanner", "rot_z_only", true,
       "robot.distance_scanner.short_range / long_range = {angle, distance}",
       {kShowRays, {"noise_range", "0:0", "parsed and ignored, as ARGoS"}}},
      {T::CameraSensor, "colored_blob_omnidirectional_camera", true,
       "colored_blob_omnidirectional_camera", "rot_z_only", true,
       "blobs {distance, angle, color={red,green,blue}}; enable() / disable()",
       {{"medium", "", "id of the <led> medium", true}, kShowRays,
        {"noise_std_dev", "0", "relative noise on the blob vector"}}},
      {T::BatterySensor, "battery", true, "battery", "default", true,
       "robot.battery.available_charge (0..1), time_left (s)",
       {{"noise_range", "0:0", "uniform noise on the charge"}}},
      {T::TurretEncoderSensor, "footbot_turret_encoder", true, "turret", "default", true,
       "robot.turret.rotation (rad)", {}},
  };
}
}  // namespace

const std::vector<DeviceRow>& DeviceTable() {
  static const std::vector<DeviceRow> table = MakeTable();
  return table;
}

const DeviceRow& GetDeviceRow(DeviceType type) {
  const DeviceRow& row = DeviceTable()[static_cast<size_t>(type)];
  assert(row.type == type);
  return row;
}

const DeviceRow* FindDevice(const std::string& xml_name, bool is_sensor) {
  for (const DeviceRow& row : DeviceTable())
    if (row.is_sensor == is_sensor && xml_name == row.xml_name) return &row;
  return nullptr;
}

}  // namespace essaim
