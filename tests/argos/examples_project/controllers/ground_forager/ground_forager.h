/* A forager that wanders, avoiding obstacles, and stops a while on each black spot its motor
 * ground sensors find, reporting it to the loop functions' board. The Lua twin is
 * controllers/lua/ground_forager.lua. */
#ifndef GROUND_FORAGER_H
#define GROUND_FORAGER_H

#include <argos3/core/control_interface/ci_controller.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_proximity_sensor.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_motor_ground_rotzonly_sensor.h>
#include <argos3/plugins/robots/generic/control_interface/ci_differential_steering_actuator.h>

#include "find_board.h"

using namespace argos;

class CGroundForager : public CCI_Controller {
 public:
  virtual void Init(TConfigurationNode& t_node);
  virtual void ControlStep();
  virtual void Reset();
  UInt32 GetFinds() const { return m_unFinds; }

 private:
  bool OnSpot();

  CCI_DifferentialSteeringActuator* m_pcWheels = nullptr;
  CCI_FootBotProximitySensor* m_pcProximity = nullptr;
  CFootBotMotorGroundRotZOnlySensor* m_pcGround = nullptr;
  CFindBoard* m_pcBoard = nullptr;
  Real m_fVelocity = 10;
  UInt32 m_unPauseTicks = 10;
  UInt32 m_unPause = 0;
  UInt32 m_unFinds = 0;
  bool m_bOnSpot = false;
};

#endif
