// ARGoS's CRangeAndBearingDefaultActuator
// (argos3/plugins/robots/generic/simulator/range_and_bearing_default_actuator.h): the <range_and_bearing
// implementation="default"> actuator a C++ controller's GetActuator returns. The data set goes to the robot after each
// controller call.
#pragma once
#include <argos3/core/simulator/actuator.h>
#include <argos3/core/simulator/entity/positional_entity.h>  // ARGoS: through rab_equipped_entity.h
#include <argos3/plugins/robots/generic/control_interface/ci_range_and_bearing_actuator.h>

namespace argos {

class CRangeAndBearingDefaultActuator : public CCI_RangeAndBearingActuator, public CSimulatedActuator {
 public:
  /// Hands the data to the robot when it changed.
  void Update() override;
  void Reset() override;
  void SetRobotDataSize(size_t un_size) { m_cData.Resize(un_size); }  // essaim: rab_data_size
};

}  // namespace argos
