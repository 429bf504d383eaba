#include "wanderer.h"

#include <argos3/core/utility/logging/argos_log.h>

void CWanderer::SWheelParams::Init(TConfigurationNode& t_node) {
  try {
    CRange<CDegrees> cWindow(CDegrees(-10), CDegrees(10));
    GetNodeAttribute(t_node, "go_straight_window", cWindow);
    GoStraight.Set(ToRadians(cWindow.GetMin()), ToRadians(cWindow.GetMax()));
    HalfWindow = ToRadians(cWindow.GetMax());
    GetNodeAttributeOrDefault(t_node, "speed", Speed, 5.0);
  } catch (CARGoSException& ex) {
    THROW_ARGOSEXCEPTION_NESTED("Error initializing the wheel parameters.", ex);
  }
}

CWanderer::CWanderer()
    : m_pcWheels(NULL),
      m_pcLEDs(NULL),
      m_pcRABAct(NULL),
      m_pcGripper(NULL),
      m_pcProximity(NULL),
      m_pcLight(NULL),
      m_pcGround(NULL),
      m_pcRABSens(NULL),
      m_pcCamera(NULL),
      m_pcPosition(NULL),
      m_pcRNG(NULL),
      m_unTicks(0) {}

void CWanderer::Init(TConfigurationNode& t_node) {
  m_pcWheels = GetActuator<CCI_DifferentialSteeringActuator>("differential_steering");
  m_pcLEDs = GetActuator<CCI_LEDsActuator>("leds");
  m_pcRABAct = GetActuator<CCI_RangeAndBearingActuator>("range_and_bearing");
  m_pcGripper = GetActuator<CCI_FootBotGripperActuator>("footbot_gripper");
  m_pcProximity = GetSensor<CCI_FootBotProximitySensor>("footbot_proximity");
  m_pcLight = GetSensor<CCI_FootBotLightSensor>("footbot_light");
  m_pcGround = GetSensor<CFootBotMotorGroundRotZOnlySensor>("footbot_motor_ground");
  m_pcRABSens = GetSensor<CCI_RangeAndBearingSensor>("range_and_bearing");
  m_pcCamera = GetSensor<CCI_ColoredBlobOmnidirectionalCameraSensor>("colored_blob_omnidirectional_camera");
  m_pcPosition = GetSensor<CCI_PositioningSensor>("positioning");
  m_sWheels.Init(GetNode(t_node, "wheels"));
  std::string strColor = "yellow";
  GetNodeAttributeOrDefault(t_node, "beacon", strColor, strColor);
  m_cBeacon.Set(strColor);
  m_pcRNG = CRandom::CreateRNG("argos");
  m_pcCamera->Enable();
  Reset();
}

void CWanderer::ControlStep() {
  ++m_unTicks;
  CVector2 cAccumulator;
  for (size_t i = 0; i < m_pcProximity->GetReadings().size(); ++i)
    cAccumulator += CVector2(m_pcProximity->GetReadings()[i].Value, m_pcProximity->GetReadings()[i].Angle);
  cAccumulator /= m_pcProximity->GetReadings().size();
  Real fLight = 0;
  for (const CCI_FootBotLightSensor::SReading& sReading : m_pcLight->GetReadings()) fLight += sReading.Value;
  CFootBotMotorGroundRotZOnlySensor::TReadings tGround = m_pcGround->GetReadings();
  const bool bOnBlack = tGround[0].Value < 0.5 && tGround[3].Value < 0.5;
  CRadians cHeading, cPitch, cRoll;
  m_pcPosition->GetReading().Orientation.ToEulerAngles(cHeading, cPitch, cRoll);
  const CVector3& cPosition = m_pcPosition->GetReading().Position;
  for (size_t i = 0; i < m_pcCamera->GetReadings().BlobList.size(); ++i) {
    CColor cColor = m_pcCamera->GetReadings().BlobList[i]->Color;
    ++m_mapSeenColors[cColor];  // colours as map keys, through operator UInt32
  }
  const CCI_RangeAndBearingSensor::TReadings& tPackets = m_pcRABSens->GetReadings();
  for (size_t i = 0; i < tPackets.size(); ++i) {
    CCI_RangeAndBearingSensor::SPacket sPacket = tPackets[i];
    if (sPacket.Data.Size() >= 4 && sPacket.Range < 50)
      RLOG << "heard " << sPacket.Data.PopFront<UInt32>() << std::endl;
  }
  CByteArray cData;
  cData << m_unTicks;
  m_pcRABAct->SetData(cData);
  m_pcRABAct->SetData(0, static_cast<UInt8>(m_unTicks));
  m_pcLEDs->SetSingleColor(12, bOnBlack ? CColor::RED : m_cBeacon);
  if (fLight > 1) m_pcGripper->LockPositive();
  CRadians cAngle = cAccumulator.Angle();
  if (m_sWheels.GoStraight.WithinMinBoundIncludedMaxBoundIncluded(cAngle) && cAccumulator.Length() < 0.1) {
    m_pcWheels->SetLinearVelocity(m_sWheels.Speed, m_sWheels.Speed);
  } else if (cAngle.GetValue() > 0) {
    m_pcWheels->SetLinearVelocity(m_sWheels.Speed, 0);
  } else {
    m_pcWheels->SetLinearVelocity(0, m_sWheels.Speed * m_pcRNG->Uniform(CRange<Real>(0.5, 1)));
  }
  if (m_unTicks % 100 == 0) {
    LOG << GetId() << " at " << cPosition << " heading " << ToDegrees(cHeading).SignedNormalize().GetValue()
        << std::endl;
    if (m_pcCamera->IsEnabled())
      m_pcCamera->Disable();
    else
      m_pcCamera->Enable();
  }
}

void CWanderer::Reset() {
  m_unTicks = 0;
  m_pcRABAct->ClearData();
  m_pcLEDs->SetAllColors(CColor::BLACK);
  m_pcLEDs->SetSingleColor(12, m_cBeacon);
}

REGISTER_CONTROLLER(CWanderer, "wanderer_controller")
