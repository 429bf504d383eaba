// ARGoS's CSimulatedSensor (argos3/core/simulator/sensor.h): the simulator side of a sensor.
// The objects a C++ controller's GetSensor returns are ARGoS's simulator classes (a
// CFootBotMotorGroundRotZOnlySensor for <footbot_motor_ground implementation="rot_z_only">),
// each reading its robot through essaim's interface to it (argos/argos_robot_io.h, inside
// essaim). essaim makes them from its own table: there is no REGISTER_SENSOR.
#pragma once
#include <argos3/core/utility/configuration/argos_exception.h>  // ARGoS: through factory.h

namespace essaim {
class ArgosRobotIo;
}

namespace argos {

class CComposableEntity;

class CSimulatedSensor {
 public:
  virtual ~CSimulatedSensor() {}
  /// ARGoS binds the sensor to its robot entity here; essaim binds it to the robot's readings
  /// (SetRobotIo) before the controller's Init, so this does nothing.
  virtual void SetRobot(CComposableEntity& c_entity) { (void)c_entity; }
  /// Takes this tick's readings (before ControlStep).
  virtual void Update() = 0;
  /// essaim: the robot's readings and commands, which outlive the sensor.
  void SetRobotIo(essaim::ArgosRobotIo* pc_io) { m_pcRobotIo = pc_io; }

 protected:
  essaim::ArgosRobotIo* m_pcRobotIo = nullptr;
};

}  // namespace argos
