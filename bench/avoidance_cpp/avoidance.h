/* The C++ twin of bench/avoidance.lua, written as an ARGoS project writes a foot-bot controller
 * (CCI_Controller, the proximity sensor and differential-steering actuator): sum the 24
 * proximity vectors; turn away when something is close, else drive straight. The same
 * arithmetic in the same order as the Lua script, so it takes the same decisions. */
#ifndef BENCH_AVOIDANCE_H
#define BENCH_AVOIDANCE_H

#include <argos3/core/control_interface/ci_controller.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_proximity_sensor.h>
#include <argos3/plugins/robots/generic/control_interface/ci_differential_steering_actuator.h>

using namespace argos;

class CAvoidance : public CCI_Controller {
 public:
  CAvoidance() : m_pcWheels(NULL), m_pcProximity(NULL) {}
  virtual ~CAvoidance() {}
  virtual void Init(TConfigurationNode& t_node);
  virtual void ControlStep();
  virtual void Reset() {}
  virtual void Destroy() {}

 private:
  CCI_DifferentialSteeringActuator* m_pcWheels;
  CCI_FootBotProximitySensor* m_pcProximity;
};

#endif
