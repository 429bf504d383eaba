#include "ground_forager.h"

#include <argos3/core/simulator/loop_functions.h>
#include <argos3/core/simulator/simulator.h>
#include <argos3/core/utility/configuration/argos_configuration.h>

void CGroundForager::Init(TConfigurationNode& t_node) {
  m_pcWheels = GetActuator<CCI_DifferentialSteeringActuator>("differential_steering");
  m_pcProximity = GetSensor<CCI_FootBotProximitySensor>("footbot_proximity");
  m_pcGround = GetSensor<CFootBotMotorGroundRotZOnlySensor>("footbot_motor_ground");
  GetNodeAttributeOrDefault(t_node, "velocity", m_fVelocity, m_fVelocity);
  GetNodeAttributeOrDefault(t_node, "pause", m_unPauseTicks, m_unPauseTicks);
  /* The loop functions exist already when controllers are initialised (ARGoS's order). */
  m_pcBoard = dynamic_cast<CFindBoard*>(&CSimulator::GetInstance().GetLoopFunctions());
  Reset();
}

void CGroundForager::Reset() {
  m_unPause = 0;
  m_unFinds = 0;
  m_bOnSpot = false;
}

/* A black spot under any motor ground sensor; off it once all read light again. */
bool CGroundForager::OnSpot() {
  const CCI_FootBotMotorGroundSensor::TReadings& tGround = m_pcGround->GetReadings();
  bool bBlack = false, bLight = true;
  for (size_t i = 0; i < tGround.size(); ++i) {
    if (tGround[i].Value < 0.25) bBlack = true;
    if (tGround[i].Value < 0.75) bLight = false;
  }
  if (bBlack && !m_bOnSpot) {
    m_bOnSpot = true;
    return true;
  }
  if (bLight) m_bOnSpot = false;
  return false;
}

void CGroundForager::ControlStep() {
  if (m_unPause > 0) {
    --m_unPause;
    m_pcWheels->SetLinearVelocity(0, 0);
    return;
  }
  if (OnSpot()) {
    ++m_unFinds;
    m_unPause = m_unPauseTicks;
    if (m_pcBoard) m_pcBoard->ReportFind();
    m_pcWheels->SetLinearVelocity(0, 0);
    return;
  }
  /* The strongest proximity reading in front decides the turn. */
  const CCI_FootBotProximitySensor::TReadings& tProx = m_pcProximity->GetReadings();
  Real fLeft = 0, fRight = 0;
  for (size_t i = 0; i < tProx.size(); ++i) {
    const Real fAngle = tProx[i].Angle.GetValue();
    if (fAngle > 0 && fAngle < 1.2 && tProx[i].Value > fLeft) fLeft = tProx[i].Value;
    if (fAngle < 0 && fAngle > -1.2 && tProx[i].Value > fRight) fRight = tProx[i].Value;
  }
  if (fLeft < 0.05 && fRight < 0.05)
    m_pcWheels->SetLinearVelocity(m_fVelocity, m_fVelocity);
  else if (fLeft > fRight)
    m_pcWheels->SetLinearVelocity(m_fVelocity, -m_fVelocity);
  else
    m_pcWheels->SetLinearVelocity(-m_fVelocity, m_fVelocity);
}

REGISTER_CONTROLLER(CGroundForager, "ground_forager_controller")
