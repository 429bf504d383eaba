// ARGoS's CLEDsDefaultActuator (argos3/plugins/robots/generic/simulator/leds_default_actuator.h): the
// <leds implementation="default"> actuator a C++ controller's GetActuator returns. The colours set go to the robot
// after each controller call.
#pragma once
#include <argos3/core/simulator/actuator.h>
#include <argos3/plugins/robots/generic/control_interface/ci_leds_actuator.h>
#include <argos3/plugins/simulator/entities/led_equipped_entity.h>

namespace argos {

class CLEDsDefaultActuator : public CCI_LEDsActuator, public CSimulatedActuator {
 public:
  /// Hands the colours that changed to the robot.
  void Update() override;
  void Reset() override;
  void SetRobotLEDs(size_t un_count);  // essaim: sized to the robot's LEDs

 private:
  TSettings m_tSent;
};

}  // namespace argos
