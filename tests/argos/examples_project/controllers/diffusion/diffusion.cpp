#include "diffusion.h"

#include <argos3/core/utility/configuration/argos_configuration.h>

CDiffusion::CDiffusion()
    : m_pcWheels(NULL),
      m_pcProximity(NULL),
      m_cAlpha(10.0f),
      m_fDelta(0.5f),
      m_fWheelVelocity(2.5f),
      m_cStraightRange(-ToRadians(m_cAlpha), ToRadians(m_cAlpha)) {}

void CDiffusion::Init(TConfigurationNode& t_node) {
  m_pcWheels = GetActuator<CCI_DifferentialSteeringActuator>("differential_steering");
  m_pcProximity = GetSensor<CCI_FootBotProximitySensor>("footbot_proximity");
  GetNodeAttributeOrDefault(t_node, "alpha", m_cAlpha, m_cAlpha);
  m_cStraightRange.Set(-ToRadians(m_cAlpha), ToRadians(m_cAlpha));
  GetNodeAttributeOrDefault(t_node, "delta", m_fDelta, m_fDelta);
  GetNodeAttributeOrDefault(t_node, "velocity", m_fWheelVelocity, m_fWheelVelocity);
}

void CDiffusion::ControlStep() {
  const CCI_FootBotProximitySensor::TReadings& tProx = m_pcProximity->GetReadings();
  CVector2 cSum;
  for (size_t i = 0; i < tProx.size(); ++i) {
    cSum += CVector2(tProx[i].Value, tProx[i].Angle);
  }
  cSum /= tProx.size();
  CRadians cAngle = cSum.Angle();
  if (m_cStraightRange.WithinMinBoundIncludedMaxBoundIncluded(cAngle) && cSum.Length() < m_fDelta) {
    m_pcWheels->SetLinearVelocity(m_fWheelVelocity, m_fWheelVelocity);
  } else if (cAngle.GetValue() > 0.0f) {
    m_pcWheels->SetLinearVelocity(m_fWheelVelocity, 0.0f);
  } else {
    m_pcWheels->SetLinearVelocity(0.0f, m_fWheelVelocity);
  }
}

REGISTER_CONTROLLER(CDiffusion, "diffusion_controller")
