#include "flocking.h"

#include <argos3/core/utility/configuration/argos_configuration.h>

#include <cmath>

static const Real PI_VALUE = 3.141592653589793;

void CFlocking::Init(TConfigurationNode& t_node) {
  m_pcWheels = GetActuator<CCI_DifferentialSteeringActuator>("differential_steering");
  m_pcLEDs = GetActuator<CCI_LEDsActuator>("leds");
  m_pcRABA = GetActuator<CCI_RangeAndBearingActuator>("range_and_bearing");
  m_pcRABS = GetSensor<CCI_RangeAndBearingSensor>("range_and_bearing");
  m_pcCamera = GetSensor<CCI_ColoredBlobOmnidirectionalCameraSensor>("colored_blob_omnidirectional_camera");
  m_pcPosition = GetSensor<CCI_PositioningSensor>("positioning");
  TConfigurationNode& tFlocking = GetNode(t_node, "flocking");
  GetNodeAttribute(tFlocking, "velocity", m_fVelocity);
  GetNodeAttribute(tFlocking, "attraction", m_fAttraction);
  m_pcCamera->Enable();
  Reset();
}

void CFlocking::Reset() {
  m_pcRABA->ClearData();
  m_pcLEDs->SetSingleColor(12, CColor::RED);
}

Real CFlocking::Heading() const {
  const CQuaternion& cOrientation = m_pcPosition->GetReading().Orientation;
  /* In (-pi, pi]: the byte sent below stays in 0..255. */
  const Real fZ = cOrientation.GetZ(), fW = cOrientation.GetW();
  return std::atan2(2.0 * fW * fZ, 1.0 - 2.0 * fZ * fZ);
}

void CFlocking::ControlStep() {
  const Real fYaw = Heading();
  m_pcRABA->SetData(0, static_cast<UInt8>((fYaw + PI_VALUE) / (2.0 * PI_VALUE) * 255.0));
  /* Alignment: the headings heard, summed in the arena's frame, turned into the robot's. */
  Real fX = std::cos(fYaw), fY = std::sin(fYaw);
  const CCI_RangeAndBearingSensor::TReadings& tPackets = m_pcRABS->GetReadings();
  for (size_t i = 0; i < tPackets.size(); ++i) {
    const Real fHeard = tPackets[i].Data[0] / 255.0 * (2.0 * PI_VALUE) - PI_VALUE;
    fX += std::cos(fHeard);
    fY += std::sin(fHeard);
  }
  const Real fAlign = std::atan2(fY, fX) - fYaw;
  Real fTX = std::cos(fAlign), fTY = std::sin(fAlign);
  /* Attraction to the red beacons seen, nearer ones more. */
  const CCI_ColoredBlobOmnidirectionalCameraSensor::SReadings& sBlobs = m_pcCamera->GetReadings();
  for (size_t i = 0; i < sBlobs.BlobList.size(); ++i) {
    const CCI_ColoredBlobOmnidirectionalCameraSensor::SBlob& sBlob = *sBlobs.BlobList[i];
    if (sBlob.Color != CColor::RED || sBlob.Distance <= 0.0) continue;
    fTX += std::cos(sBlob.Angle.GetValue()) * m_fAttraction / sBlob.Distance;
    fTY += std::sin(sBlob.Angle.GetValue()) * m_fAttraction / sBlob.Distance;
  }
  const Real fTurn = std::atan2(fTY, fTX);
  m_pcWheels->SetLinearVelocity(m_fVelocity - m_fVelocity * fTurn, m_fVelocity + m_fVelocity * fTurn);
}

REGISTER_CONTROLLER(CFlocking, "flocking_controller")
