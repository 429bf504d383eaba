// ARGoS's CCI_RangeAndBearingSensor
// (argos3/plugins/robots/generic/control_interface/ci_range_and_bearing_sensor.h): the packets
// received this tick, each with the sender's range (cm), bearings (rad) and data.
#pragma once
#include <argos3/core/control_interface/ci_sensor.h>
#include <argos3/core/utility/datatypes/byte_array.h>
#include <argos3/core/utility/datatypes/datatypes.h>
#include <argos3/core/utility/math/quaternion.h>

#include <vector>

namespace argos {

class CCI_RangeAndBearingSensor : public CCI_Sensor {
 public:
  struct SPacket {
    Real Range;
    CRadians HorizontalBearing;
    /// Angle from the robot's horizontal plane: 0 for robots on the same plane.
    CRadians VerticalBearing;
    CByteArray Data;
    SPacket() : Range(0.0) {}
  };
  typedef std::vector<SPacket> TReadings;

  virtual ~CCI_RangeAndBearingSensor() {}
  const TReadings& GetReadings() const { return m_tReadings; }

 protected:
  TReadings m_tReadings;
};

}  // namespace argos
