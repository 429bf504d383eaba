#include "devices/device_functions.h"

#include <algorithm>

namespace essaim {

namespace {
void ReserveRabPackets(const InitContext& c, const DeviceConfig&, const RobotDef&, RobotState& r) {
  // Bounded (a full n-1 per robot would be O(n^2) memory): the vector grows to the densest
  // neighbourhood seen, then stays.
  r.rd.rab.reserve(std::min<size_t>(c.model.robots.size(), 128));
}

void ReserveScannerCandidates(const InitContext&, const DeviceConfig&, const RobotDef&, RobotState& r) {
  // The long sensors' sectors turn: a new densest one may come long after the first ticks.
  for (RayCandidates* list : {&r.scanner_candidates, &r.scanner_wedge}) {
    list->items.reserve(64);
    list->scratch.reserve(64);
  }
}

using T = DeviceType;
using A = ActPhase;
// Each entry adapts a device's own function (devices.h) to the row's signature.
constexpr std::array<DeviceFunctions, kDeviceCount> kRows = {{
    // ---- actuators
    {T::WheelsActuator, [](const auto&, const auto& d, const auto&, auto& r) { InitWheelNoise(d, r); }, A::OwnState,
     [](const auto& c, const auto& d, const auto&, auto& r) { ActWheels(&d, r, c.physics); }, nullptr},
    {T::LedsActuator, nullptr, A::OwnState, [](const auto&, const auto&, const auto&, auto& r) { ActLeds(r); },
     nullptr},
    {T::RabActuator, nullptr, A::OwnState, [](const auto&, const auto&, const auto&, auto& r) { ActRab(r); }, nullptr},
    {T::ScannerActuator, nullptr, A::OwnState, [](const auto&, const auto&, const auto&, auto& r) { ActScanner(r); },
     nullptr},
    // The gripper reads the turret angle before the turret turns, as in one ordered pass.
    {T::GripperActuator, nullptr, A::Joints,
     [](const auto& c, const auto&, const auto&, auto& r) { ActGripper(r, c.physics); }, nullptr},
    {T::TurretActuator, nullptr, A::Joints,
     [](const auto& c, const auto&, const auto&, auto& r) { ActTurret(r, c.physics, c.dt); }, nullptr},
    // ---- sensors
    {T::WheelsSensor, nullptr, A::None, nullptr,
     [](const auto& c, const auto& d, const auto&, auto& r) { SenseWheels(d, r, c.dt); }},
    // Its reading is visible in init(): the initial pose.
    {T::PositioningSensor,
     [](const auto& c, const auto& d, const auto&, auto& r) { SensePositioning(d, r, c.physics); }, A::None, nullptr,
     [](const auto& c, const auto& d, const auto&, auto& r) { SensePositioning(d, r, c.physics); }},
    {T::ProximitySensor,
     [](const auto&, const auto&, const auto&, auto& r) { r.proximity_candidates.items.reserve(16); }, A::None, nullptr,
     [](const auto& c, const auto& d, const auto&, auto& r) { SenseProximity(d, r, c.physics); }},
    {T::LightSensor, nullptr, A::None, nullptr,
     [](const auto& c, const auto& d, const auto& def, auto& r) { SenseLight(d, c.model, def, r, c.physics); }},
    {T::BaseGroundSensor, nullptr, A::None, nullptr,
     [](const auto& c, const auto& d, const auto&, auto& r) { SenseBaseGround(d, r, c.physics, c.floor); }},
    {T::MotorGroundSensor, nullptr, A::None, nullptr,
     [](const auto& c, const auto& d, const auto&, auto& r) { SenseMotorGround(d, r, c.physics, c.floor); }},
    {T::RabSensor, ReserveRabPackets, A::None, nullptr,
     [](const auto& c, const auto& d, const auto&, auto& r) { SenseRab(c, d, r); }},
    {T::ScannerSensor, ReserveScannerCandidates, A::None, nullptr,
     [](const auto& c, const auto&, const auto&, auto& r) { SenseScanner(r, c.physics); }},
    {T::CameraSensor, [](const auto&, const auto&, const auto&, auto& r) { r.rd.blobs.reserve(64); }, A::None, nullptr,
     [](const auto& c, const auto& d, const auto& def, auto& r) { SenseCamera(c, d, def, r); }},
    {T::BatterySensor, nullptr, A::None, nullptr,
     [](const auto& c, const auto& d, const auto& def, auto& r) { SenseBattery(d, def.battery, r, c.dt); }},
    {T::TurretEncoderSensor, nullptr, A::None, nullptr,
     [](const auto&, const auto&, const auto&, auto& r) { SenseTurretEncoder(r); }},
}};

// Every DeviceType has its row, in enum order, and the row has what its kind needs.
constexpr bool RowsComplete() {
  for (int i = 0; i < kDeviceCount; ++i) {
    const DeviceFunctions& f = kRows[i];
    const bool sensor = kDeviceRows[i].is_sensor;
    if (static_cast<int>(f.type) != i) return false;
    if (sensor && (!f.sense || f.act || f.act_phase != ActPhase::None)) return false;
    if (!sensor && (!f.act || f.sense || f.act_phase == ActPhase::None)) return false;
  }
  return true;
}
static_assert(RowsComplete(), "device_functions.cpp: a row per DeviceType in enum order; sensors sense, actuators act");
}  // namespace

const DeviceFunctions& FunctionsOf(DeviceType type) { return kRows[static_cast<int>(type)]; }

}  // namespace essaim
