// The one table of the sensors and actuators a C++ controller may declare: (tag,
// implementation) → ARGoS's simulator class, and whether ARGoS's Init enables it.
#include "argos/api/devices.h"

#include <argos3/plugins/robots/foot-bot/simulator/footbot_base_ground_rotzonly_sensor.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_distance_scanner_default_actuator.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_distance_scanner_rotzonly_sensor.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_gripper_default_actuator.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_light_rotzonly_sensor.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_motor_ground_rotzonly_sensor.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_proximity_default_sensor.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_turret_default_actuator.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_turret_encoder_default_sensor.h>
#include <argos3/plugins/robots/generic/simulator/battery_default_sensor.h>
#include <argos3/plugins/robots/generic/simulator/colored_blob_omnidirectional_camera_rotzonly_sensor.h>
#include <argos3/plugins/robots/generic/simulator/differential_steering_default_actuator.h>
#include <argos3/plugins/robots/generic/simulator/differential_steering_default_sensor.h>
#include <argos3/plugins/robots/generic/simulator/leds_default_actuator.h>
#include <argos3/plugins/robots/generic/simulator/positioning_default_sensor.h>
#include <argos3/plugins/robots/generic/simulator/range_and_bearing_default_actuator.h>
#include <argos3/plugins/robots/generic/simulator/range_and_bearing_medium_sensor.h>

#include "argos/argos_robot_io.h"

namespace essaim {
namespace {
using argos::CCI_Actuator;
using argos::CCI_Sensor;

// What ARGoS's Init does to the enabled flag: the proximity sensor leaves it (its inner
// sensor enables itself), the camera disables itself, the others enable themselves.
enum class Start { Leave, Enable, Disable };

struct SensorRow {
  const char* tag;
  const char* implementation;
  Start start;
  argos::CSimulatedSensor* (*make)(ArgosRobotIo* io);
};
struct ActuatorRow {
  const char* tag;
  const char* implementation;
  argos::CSimulatedActuator* (*make)(ArgosRobotIo* io);
};

template <typename T>
argos::CSimulatedSensor* MakeSensor(ArgosRobotIo*) {
  return new T;
}
template <typename T>
argos::CSimulatedActuator* MakeActuator(ArgosRobotIo*) {
  return new T;
}
// The LEDs and the range-and-bearing data are sized to the robot's.
argos::CSimulatedActuator* MakeLeds(ArgosRobotIo* io) {
  auto* leds = new argos::CLEDsDefaultActuator;
  leds->SetRobotLEDs(static_cast<size_t>(io->LedCount()));
  return leds;
}
argos::CSimulatedActuator* MakeRab(ArgosRobotIo* io) {
  auto* rab = new argos::CRangeAndBearingDefaultActuator;
  rab->SetRobotDataSize(static_cast<size_t>(io->RabDataSize()));
  return rab;
}

const SensorRow kSensors[] = {
    {"footbot_proximity", "default", Start::Leave, MakeSensor<argos::CFootBotProximityDefaultSensor>},
    {"footbot_light", "rot_z_only", Start::Enable, MakeSensor<argos::CFootBotLightRotZOnlySensor>},
    {"footbot_motor_ground", "rot_z_only", Start::Enable, MakeSensor<argos::CFootBotMotorGroundRotZOnlySensor>},
    {"footbot_base_ground", "rot_z_only", Start::Enable, MakeSensor<argos::CFootBotBaseGroundRotZOnlySensor>},
    {"footbot_distance_scanner", "rot_z_only", Start::Enable, MakeSensor<argos::CFootBotDistanceScannerRotZOnlySensor>},
    {"footbot_turret_encoder", "default", Start::Enable, MakeSensor<argos::CFootBotTurretEncoderDefaultSensor>},
    {"differential_steering", "default", Start::Enable, MakeSensor<argos::CDifferentialSteeringDefaultSensor>},
    {"range_and_bearing", "medium", Start::Enable, MakeSensor<argos::CRangeAndBearingMediumSensor>},
    {"colored_blob_omnidirectional_camera", "rot_z_only", Start::Disable,
     MakeSensor<argos::CColoredBlobOmnidirectionalCameraRotZOnlySensor>},
    {"positioning", "default", Start::Enable, MakeSensor<argos::CPositioningDefaultSensor>},
    {"battery", "default", Start::Enable, MakeSensor<argos::CBatteryDefaultSensor>},
};

const ActuatorRow kActuators[] = {
    {"differential_steering", "default", MakeActuator<argos::CDifferentialSteeringDefaultActuator>},
    {"leds", "default", MakeLeds},
    {"range_and_bearing", "default", MakeRab},
    {"footbot_gripper", "default", MakeActuator<argos::CFootBotGripperDefaultActuator>},
    {"footbot_turret", "default", MakeActuator<argos::CFootBotTurretDefaultActuator>},
    {"footbot_distance_scanner", "default", MakeActuator<argos::CFootBotDistanceScannerDefaultActuator>},
};

template <typename Row, size_t N>
const Row* Find(const Row (&rows)[N], const ArgosDeviceDecl& device) {
  for (const Row& row : rows)
    if (device.tag == row.tag && device.implementation == row.implementation) return &row;
  return nullptr;
}

// "tag (implementation), ..." of one table, for the error.
template <typename Row, size_t N>
std::string Known(const Row (&rows)[N]) {
  std::string out;
  for (const Row& row : rows) out += (out.empty() ? "" : ", ") + std::string(row.tag) + " (" + row.implementation + ")";
  return out;
}

[[noreturn]] void Unknown(const ArgosDeviceDecl& device, const std::string& where, const std::string& known) {
  const char* kind = device.sensor ? "sensor" : "actuator";
  throw argos::CARGoSException::Configuration(where + ": essaim has no " + kind + " <" + device.tag +
                                              " implementation=\"" + device.implementation +
                                              "\"> for C++ controllers; it has " + known);
}

void AddSensor(const ArgosDeviceDecl& device, ArgosRobotIo* io, const std::string& where, ArgosControllerSlot& slot) {
  const SensorRow* row = Find(kSensors, device);
  if (!row) Unknown(device, where, Known(kSensors));
  slot.sensors.emplace_back(row->make(io));
  argos::CSimulatedSensor& made = *slot.sensors.back();
  made.SetRobotIo(io);
  auto* sensor = dynamic_cast<CCI_Sensor*>(&made);
  if (row->start == Start::Enable) sensor->Enable();
  if (row->start == Start::Disable) sensor->Disable();
  slot.controller->AddSensor(device.tag, sensor);
}

void AddActuator(const ArgosDeviceDecl& device, ArgosRobotIo* io, const std::string& where, ArgosControllerSlot& slot) {
  const ActuatorRow* row = Find(kActuators, device);
  if (!row) Unknown(device, where, Known(kActuators));
  slot.actuators.emplace_back(row->make(io));
  argos::CSimulatedActuator& made = *slot.actuators.back();
  made.SetRobotIo(io);
  slot.controller->AddActuator(device.tag, dynamic_cast<CCI_Actuator*>(&made));
}
}  // namespace

void AddDevice(const ArgosDeviceDecl& device, ArgosRobotIo* io, const std::string& where, ArgosControllerSlot& slot) {
  if (device.sensor)
    AddSensor(device, io, where, slot);
  else
    AddActuator(device, io, where, slot);
}

}  // namespace essaim
