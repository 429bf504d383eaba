#include "avoidance.h"

#include <algorithm>
#include <cmath>

void CAvoidance::Init(TConfigurationNode& /* t_node */) {
  m_pcWheels = GetActuator<CCI_DifferentialSteeringActuator>("differential_steering");
  m_pcProximity = GetSensor<CCI_FootBotProximitySensor>("footbot_proximity");
}

void CAvoidance::ControlStep() {
  const CCI_FootBotProximitySensor::TReadings& tProx = m_pcProximity->GetReadings();
  Real fX = 0, fY = 0;
  for (size_t i = 0; i < tProx.size(); ++i) {
    const Real fAngle = tProx[i].Angle.GetValue();
    const Real fVX = tProx[i].Value * std::cos(fAngle);
    const Real fVY = tProx[i].Value * std::sin(fAngle);
    fX = fX + fVX;
    fY = fY + fVY;
  }
  const Real fLength = std::sqrt(fX * fX + fY * fY);
  const Real fAngle = std::atan2(fY, fX);
  if (fLength > 0.2) {
    /* Lua's math.max(0.5, x): x only when 0.5 < x, as std::max */
    const Real fSpeed = std::max(0.5, std::cos(fAngle)) * 15;
    if (fAngle > 0) {
      m_pcWheels->SetLinearVelocity(fSpeed, 0);
    } else {
      m_pcWheels->SetLinearVelocity(0, fSpeed);
    }
  } else {
    m_pcWheels->SetLinearVelocity(15, 15);
  }
}

REGISTER_CONTROLLER(CAvoidance, "avoidance_controller")
