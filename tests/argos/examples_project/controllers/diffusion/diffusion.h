/* Obstacle avoidance by diffusion: drive straight unless the proximity readings, summed as
 * vectors, point into the front sector or are strong; then turn away. The Lua twin is
 * controllers/lua/diffusion.lua: the same arithmetic in the same order. */
#ifndef DIFFUSION_H
#define DIFFUSION_H

#include <argos3/core/control_interface/ci_controller.h>
#include <argos3/core/utility/math/vector2.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_proximity_sensor.h>
#include <argos3/plugins/robots/generic/control_interface/ci_differential_steering_actuator.h>

using namespace argos;

class CDiffusion : public CCI_Controller {
 public:
  CDiffusion();
  virtual ~CDiffusion() {}
  virtual void Init(TConfigurationNode& t_node);
  virtual void ControlStep();
  virtual void Reset() {}
  virtual void Destroy() {}

 private:
  CCI_DifferentialSteeringActuator* m_pcWheels;
  CCI_FootBotProximitySensor* m_pcProximity;
  CDegrees m_cAlpha;
  Real m_fDelta;
  Real m_fWheelVelocity;
  CRange<CRadians> m_cStraightRange;
};

#endif
