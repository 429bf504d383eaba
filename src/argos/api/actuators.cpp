// The actuators a C++ controller commands: ARGoS's control-interface classes, whose
// commands reach the robot (ArgosRobotIo) either as they are set (wheels, turret, scanner)
// or, for those that keep them in ARGoS's own fields (LEDs, range-and-bearing data,
// gripper), after each controller call, where ARGoS's Update would hand them over; either
// way they act at the next tick's act stage.
#include <argos3/plugins/robots/foot-bot/simulator/footbot_distance_scanner_default_actuator.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_gripper_default_actuator.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_turret_default_actuator.h>
#include <argos3/plugins/robots/generic/simulator/differential_steering_default_actuator.h>
#include <argos3/plugins/robots/generic/simulator/leds_default_actuator.h>
#include <argos3/plugins/robots/generic/simulator/range_and_bearing_default_actuator.h>

#include <cmath>
#include <cstring>

#include "argos/argos_robot_io.h"

namespace argos {

// ---- control interfaces' own parts

CRadians CCI_FootBotGripperActuator::UNLOCKED(0.0);
CRadians CCI_FootBotGripperActuator::LOCKED_POSITIVE(ARGOS_PI / 2);
CRadians CCI_FootBotGripperActuator::LOCKED_NEGATIVE(-ARGOS_PI / 2);

void CCI_FootBotGripperActuator::SetAperture(const CRadians& c_aperture) {
  m_cAperture = c_aperture;
  m_cAperture.SignedNormalize();
  CRange<CRadians>(LOCKED_NEGATIVE, LOCKED_POSITIVE).TruncValue(m_cAperture);
}

const CRange<SInt32> CCI_FootBotTurretActuator::SPEED_RANGE(-4, 4);
const CRange<Real> CCI_FootBotTurretActuator::NORMALIZED_SPEED_RANGE(-1.0, 1.0);

namespace {
// ARGoS indexes its vector unchecked; an index past the LEDs would write outside it.
void CheckLed(UInt32 un_led, size_t un_count) {
  if (un_led >= un_count)
    THROW_ARGOSEXCEPTION("CCI_LEDsActuator: LED " << un_led << " does not exist (the robot has " << un_count
                                                  << ", 0 to " << un_count - 1 << ")");
}
}  // namespace

void CCI_LEDsActuator::SetSingleColor(UInt32 un_led_number, const CColor& c_color) {
  CheckLed(un_led_number, m_tSettings.size());
  m_tSettings[un_led_number] = c_color;
}
void CCI_LEDsActuator::SetAllColors(const CColor& c_color) {
  for (CColor& cSetting : m_tSettings) cSetting = c_color;
}
void CCI_LEDsActuator::SetAllColors(const TSettings& c_colors) {
  if (c_colors.size() != m_tSettings.size())
    THROW_ARGOSEXCEPTION("CCI_LEDsActuator::SetAllColors: " << c_colors.size() << " colours for " << m_tSettings.size()
                                                            << " LEDs");
  m_tSettings = c_colors;
}
void CCI_LEDsActuator::SetSingleIntensity(UInt32 un_led_number, UInt8 un_intensity) {
  CheckLed(un_led_number, m_tSettings.size());
  m_tSettings[un_led_number].SetAlpha(un_intensity);
}
void CCI_LEDsActuator::SetAllIntensities(UInt8 un_intensity) {
  for (CColor& cSetting : m_tSettings) cSetting.SetAlpha(un_intensity);
}

void CCI_RangeAndBearingActuator::SetData(const CByteArray& c_data) {
  if (c_data.Size() != m_cData.Size())
    THROW_ARGOSEXCEPTION("CCI_RangeAndBearingActuator::SetData() : data size does not match, expected "
                         << m_cData.Size() << ", got " << c_data.Size());
  m_cData = c_data;  // same size: the buffer is reused
}

// ---- simulator classes

void CDifferentialSteeringDefaultActuator::SetLinearVelocity(Real f_left_velocity, Real f_right_velocity) {
  if (!m_pcRobotIo->SetWheels(f_left_velocity, f_right_velocity))
    THROW_ARGOSEXCEPTION("SetLinearVelocity(" << f_left_velocity << ", " << f_right_velocity
                                              << "): a wheel velocity is not a finite number");
  m_fCurrentVelocity[0] = f_left_velocity * 0.01;  // ARGoS keeps them in m/s
  m_fCurrentVelocity[1] = f_right_velocity * 0.01;
}
void CDifferentialSteeringDefaultActuator::Reset() {
  m_pcRobotIo->SetWheels(0, 0);
  m_fCurrentVelocity[0] = m_fCurrentVelocity[1] = 0;
}

// ARGoS's actuator sets every LED at each act, black until told otherwise: the first Update
// sends them all (no LED is transparent black), later ones what changed.
void CLEDsDefaultActuator::SetRobotLEDs(size_t un_count) {
  m_tSettings.assign(un_count, CColor::BLACK);
  m_tSent.assign(un_count, CColor(0, 0, 0, 0));
}
void CLEDsDefaultActuator::Update() {
  for (size_t i = 0; i < m_tSettings.size(); ++i) {
    if (m_tSettings[i] == m_tSent[i]) continue;
    const CColor& cColor = m_tSettings[i];
    m_pcRobotIo->SetLed(static_cast<int>(i), {cColor.GetRed(), cColor.GetGreen(), cColor.GetBlue()}, cColor.GetAlpha());
    m_tSent[i] = cColor;
  }
}
void CLEDsDefaultActuator::Reset() { SetAllColors(CColor::BLACK); }

// Written into the robot's payload only when it changed: most robots send the same bytes.
void CRangeAndBearingDefaultActuator::Update() {
  UInt8* punOut = m_pcRobotIo->RabData();
  const size_t unSize = Min(m_cData.Size(), static_cast<size_t>(m_pcRobotIo->RabDataSize()));
  if (unSize > 0 && std::memcmp(punOut, m_cData.ToCArray(), unSize) != 0)
    std::memcpy(punOut, m_cData.ToCArray(), unSize);
}
void CRangeAndBearingDefaultActuator::Reset() { m_cData.Zero(); }

void CFootBotGripperDefaultActuator::Update() {
  if (m_cAperture.GetValue() == m_fSent) return;
  m_pcRobotIo->SetGripperAperture(m_cAperture.GetValue());
  m_fSent = m_cAperture.GetValue();
}
void CFootBotGripperDefaultActuator::Reset() { Unlock(); }

void CFootBotTurretDefaultActuator::SetRotation(const CRadians& c_angle) {
  m_pcRobotIo->TurretSetRotation(c_angle.GetValue());
}
void CFootBotTurretDefaultActuator::SetRotationSpeed(SInt32 n_speed_pulses) {
  m_pcRobotIo->TurretSetRotationSpeed(n_speed_pulses);
}
void CFootBotTurretDefaultActuator::SetMode(ETurretModes e_mode) {
  static const essaim::ArgosTurretMode kModes[] = {essaim::ArgosTurretMode::Off, essaim::ArgosTurretMode::Passive,
                                                   essaim::ArgosTurretMode::Speed, essaim::ArgosTurretMode::Position};
  m_pcRobotIo->TurretSetMode(kModes[e_mode]);
}
void CFootBotTurretDefaultActuator::Reset() { SetMode(MODE_OFF); }

void CFootBotDistanceScannerDefaultActuator::SetAngle(const CRadians& c_angle) {
  m_pcRobotIo->ScannerSetAngle(c_angle.GetValue());
}
void CFootBotDistanceScannerDefaultActuator::SetRPM(Real f_rpm) { m_pcRobotIo->ScannerSetRpm(f_rpm); }
void CFootBotDistanceScannerDefaultActuator::Enable() { m_pcRobotIo->ScannerEnable(); }
void CFootBotDistanceScannerDefaultActuator::Disable() { m_pcRobotIo->ScannerDisable(); }
void CFootBotDistanceScannerDefaultActuator::Reset() { m_pcRobotIo->ScannerDisable(); }

}  // namespace argos
