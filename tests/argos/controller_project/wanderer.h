// A foot-bot controller using what the census's controllers use: proximity diffusion with a
// go-straight window in degrees, light and ground readings, the beacon LED, the camera
// toggled, range-and-bearing bytes both ways, positioning's heading, CRandom, LOG.
#pragma once
#include <argos3/core/control_interface/ci_controller.h>
#include <argos3/core/utility/math/rng.h>
#include <argos3/core/utility/math/vector2.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_gripper_actuator.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_light_sensor.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_proximity_sensor.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_motor_ground_rotzonly_sensor.h>
#include <argos3/plugins/robots/generic/control_interface/ci_colored_blob_omnidirectional_camera_sensor.h>
#include <argos3/plugins/robots/generic/control_interface/ci_differential_steering_actuator.h>
#include <argos3/plugins/robots/generic/control_interface/ci_leds_actuator.h>
#include <argos3/plugins/robots/generic/control_interface/ci_positioning_sensor.h>
#include <argos3/plugins/robots/generic/control_interface/ci_range_and_bearing_actuator.h>
#include <argos3/plugins/robots/generic/control_interface/ci_range_and_bearing_sensor.h>

#include <map>

using namespace argos;

class CWanderer : public CCI_Controller {
 public:
  struct SWheelParams {
    CRadians HalfWindow;
    CRange<CRadians> GoStraight;
    Real Speed;
    void Init(TConfigurationNode& t_node);
  };

  CWanderer();
  virtual ~CWanderer() {}
  virtual void Init(TConfigurationNode& t_node);
  virtual void ControlStep();
  virtual void Reset();
  virtual void Destroy() {}

 private:
  CCI_DifferentialSteeringActuator* m_pcWheels;
  CCI_LEDsActuator* m_pcLEDs;
  CCI_RangeAndBearingActuator* m_pcRABAct;
  CCI_FootBotGripperActuator* m_pcGripper;
  CCI_FootBotProximitySensor* m_pcProximity;
  CCI_FootBotLightSensor* m_pcLight;
  CFootBotMotorGroundRotZOnlySensor* m_pcGround;
  CCI_RangeAndBearingSensor* m_pcRABSens;
  CCI_ColoredBlobOmnidirectionalCameraSensor* m_pcCamera;
  CCI_PositioningSensor* m_pcPosition;
  CRandom::CRNG* m_pcRNG;
  SWheelParams m_sWheels;
  std::map<UInt32, UInt32> m_mapSeenColors;
  CColor m_cBeacon;
  UInt32 m_unTicks;
};
