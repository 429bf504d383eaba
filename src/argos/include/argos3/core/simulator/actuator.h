// ARGoS's CSimulatedActuator (argos3/core/simulator/actuator.h): the simulator side of an
// actuator. As the sensors (sensor.h), the objects GetActuator returns are ARGoS's simulator
// classes over essaim's interface to the robot. Their commands are handed to the robot as
// they are set and act at the next tick's act stage, where ARGoS's Update would apply them.
#pragma once
#include <argos3/core/utility/configuration/argos_exception.h>  // ARGoS: through factory.h

namespace essaim {
class ArgosRobotIo;
}

namespace argos {

class CComposableEntity;

class CSimulatedActuator {
 public:
  virtual ~CSimulatedActuator() {}
  virtual void SetRobot(CComposableEntity& c_entity) { (void)c_entity; }
  /// ARGoS applies the commands here; essaim's are applied as they are set.
  virtual void Update() {}
  void SetRobotIo(essaim::ArgosRobotIo* pc_io) { m_pcRobotIo = pc_io; }

 protected:
  essaim::ArgosRobotIo* m_pcRobotIo = nullptr;
};

}  // namespace argos
