/* Flocking over range-and-bearing and the camera: each robot broadcasts its heading (one byte),
 * aligns with the headings it hears, and is drawn to the red beacons it sees. The Lua twin is
 * controllers/lua/flocking.lua. */
#ifndef FLOCKING_H
#define FLOCKING_H

#include <argos3/core/control_interface/ci_controller.h>
#include <argos3/plugins/robots/generic/control_interface/ci_colored_blob_omnidirectional_camera_sensor.h>
#include <argos3/plugins/robots/generic/control_interface/ci_differential_steering_actuator.h>
#include <argos3/plugins/robots/generic/control_interface/ci_leds_actuator.h>
#include <argos3/plugins/robots/generic/control_interface/ci_positioning_sensor.h>
#include <argos3/plugins/robots/generic/control_interface/ci_range_and_bearing_actuator.h>
#include <argos3/plugins/robots/generic/control_interface/ci_range_and_bearing_sensor.h>

using namespace argos;

class CFlocking : public CCI_Controller {
 public:
  virtual void Init(TConfigurationNode& t_node);
  virtual void ControlStep();
  virtual void Reset();

 private:
  Real Heading() const;

  CCI_DifferentialSteeringActuator* m_pcWheels = nullptr;
  CCI_LEDsActuator* m_pcLEDs = nullptr;
  CCI_RangeAndBearingActuator* m_pcRABA = nullptr;
  CCI_RangeAndBearingSensor* m_pcRABS = nullptr;
  CCI_ColoredBlobOmnidirectionalCameraSensor* m_pcCamera = nullptr;
  CCI_PositioningSensor* m_pcPosition = nullptr;
  Real m_fVelocity = 5;
  Real m_fAttraction = 20;
};

#endif
