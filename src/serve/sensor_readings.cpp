#include "serve/sensor_readings.h"

#include "model/device_table.h"

namespace essaim {

namespace {
Value Number(double d) { return Value::OfNumber(d); }

template <size_t N>
Value Numbers(const double (&values)[N]) {
  Value v = Value::EmptyList();
  for (double x : values) v.list.push_back(Number(x));
  return v;
}

Value Wheels(const Readings& rd) {
  return Value::MapOf({{"velocity_left", Number(rd.velocity_left)},
                       {"velocity_right", Number(rd.velocity_right)},
                       {"distance_left", Number(rd.distance_left)},
                       {"distance_right", Number(rd.distance_right)}});
}

Value Positioning(const Readings& rd) {
  return Value::MapOf(
      {{"position",
        Value::MapOf({{"x", Number(rd.position.x())}, {"y", Number(rd.position.y())}, {"z", Number(rd.position.z())}})},
       {"orientation", Value::MapOf({{"w", Number(rd.quat_w)},
                                     {"x", Number(rd.quat_x)},
                                     {"y", Number(rd.quat_y)},
                                     {"z", Number(rd.quat_z)}})}});
}

Value Rab(const Readings& rd) {
  Value v = Value::EmptyList();
  for (const RabPacket& p : rd.rab) {
    Value data = Value::EmptyList();
    for (int k = 0; k < p.size && p.data; ++k) data.list.push_back(Value::OfInteger(p.data[k]));
    v.list.push_back(Value::MapOf({{"range", Number(p.range)},
                                   {"horizontal_bearing", Number(p.horizontal_bearing)},
                                   {"vertical_bearing", Number(p.vertical_bearing)},
                                   {"data", std::move(data)}}));
  }
  return v;
}

Value Blobs(const Readings& rd) {
  Value v = Value::EmptyList();
  for (const Blob& b : rd.blobs) {
    Value color = Value::EmptyList();
    color.list = {Value::OfInteger(b.color.r), Value::OfInteger(b.color.g), Value::OfInteger(b.color.b)};
    v.list.push_back(Value::MapOf({{"distance", Number(b.distance)}, {"angle", Number(b.angle)}, {"color", color}}));
  }
  return Value::MapOf({{"blobs", std::move(v)}});
}

Value Scans(const ScanReading* scans, int count) {
  Value v = Value::EmptyList();
  for (int k = 0; k < count; ++k)
    v.list.push_back(Value::MapOf({{"angle", Number(scans[k].angle)}, {"distance", Number(scans[k].distance)}}));
  return v;
}

Value Reading(DeviceType type, const Readings& rd) {
  switch (type) {
    case DeviceType::WheelsSensor:
      return Wheels(rd);
    case DeviceType::PositioningSensor:
      return Positioning(rd);
    case DeviceType::ProximitySensor:
      return Numbers(rd.proximity);
    case DeviceType::LightSensor:
      return Numbers(rd.light);
    case DeviceType::BaseGroundSensor:
      return Numbers(rd.base_ground);
    case DeviceType::MotorGroundSensor:
      return Numbers(rd.motor_ground);
    case DeviceType::RabSensor:
      return Rab(rd);
    case DeviceType::CameraSensor:
      return Blobs(rd);
    case DeviceType::BatterySensor:
      return Value::MapOf(
          {{"available_charge", Number(rd.battery_charge)}, {"time_left", Number(rd.battery_time_left)}});
    case DeviceType::TurretEncoderSensor:
      return Value::MapOf({{"rotation", Number(rd.turret_rotation)}});
    case DeviceType::ScannerSensor:
      return Value::MapOf({{"short_range", Scans(rd.scanner_short, rd.scanner_short_count)},
                           {"long_range", Scans(rd.scanner_long, rd.scanner_long_count)}});
    default:
      return Value();
  }
}
}  // namespace

Value SensorReadingsValue(const ControllerDef& c, const RobotState& r) {
  Value v = Value::EmptyMap();
  for (const DeviceConfig& d : c.sensors) v.Set(GetDeviceRow(d.type).lua_key, Reading(d.type, r.rd));
  return v;
}

Value ControllerKindValue(const ControllerDef& c) {
  if (!c.Cpp()) return Value::MapOf({{"kind", Value::OfString("lua")}, {"script", Value::OfString(c.script)}});
  return Value::MapOf({{"kind", Value::OfString("cpp")},
                       {"label", Value::OfString(c.label)},
                       {"library", Value::OfString(c.library)},
                       {"note", Value::OfString("runs a C++ controller (" + c.label +
                                                "): no Lua globals to inspect; readings are its sensors'")}});
}

}  // namespace essaim
