#include "model/device_table.h"

namespace essaim {

const char* CostName(DeviceCost cost) {
  switch (cost) {
    case DeviceCost::Fixed:
      return "fixed per robot";
    case DeviceCost::PerRay:
      return "per ray (shapes near the robot)";
    case DeviceCost::PerFloorPoint:
      return "per floor point";
    case DeviceCost::PerJoint:
      return "per joint (one thread)";
    case DeviceCost::PerPartner:
      return "per partner in range";
    case DeviceCost::PerLed:
      return "per LED in view";
  }
  return "";
}

const DeviceRow* FindDevice(const std::string& xml_name, bool is_sensor) {
  for (const DeviceRow& row : kDeviceRows)
    if (row.is_sensor == is_sensor && xml_name == row.xml_name) return &row;
  return nullptr;
}

}  // namespace essaim
