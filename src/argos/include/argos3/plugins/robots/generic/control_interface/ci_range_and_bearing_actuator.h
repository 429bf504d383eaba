// ARGoS's CCI_RangeAndBearingActuator
// (argos3/plugins/robots/generic/control_interface/ci_range_and_bearing_actuator.h): the
// bytes the robot sends from the next tick on; their number is the robot's rab_data_size.
#pragma once
#include <argos3/core/control_interface/ci_actuator.h>
#include <argos3/core/utility/datatypes/byte_array.h>

namespace argos {

class CCI_RangeAndBearingActuator : public CCI_Actuator {
 public:
  virtual ~CCI_RangeAndBearingActuator() {}
  size_t GetSize() const { return m_cData.Size(); }
  /// Throws unless `c_data` has GetSize() bytes.
  void SetData(const CByteArray& c_data);
  /// Throws when `un_idx` is not below GetSize() (CByteArray's check, as ARGoS's).
  void SetData(size_t un_idx, UInt8 un_value) { m_cData[un_idx] = un_value; }
  void ClearData() { m_cData.Zero(); }

 protected:
  CByteArray m_cData;
};

}  // namespace argos
