// ARGoS's CCI_FootBotBaseGroundSensor
// (argos3/plugins/robots/foot-bot/control_interface/ci_footbot_base_ground_sensor.h): the 8
// ground sensors under the base, Value 0 or 1 (ARGoS's threshold at 0.5) and the sensor's
// Offset from the robot's centre in cm.
#pragma once
#include <argos3/core/control_interface/ci_sensor.h>
#include <argos3/core/utility/math/vector2.h>

#include <ostream>
#include <vector>

namespace argos {

class CCI_FootBotBaseGroundSensor : virtual public CCI_Sensor {
 public:
  struct SReading {
    Real Value;
    CVector2 Offset;
    SReading() : Value(0.0) {}
    SReading(Real f_value, const CVector2& c_offset) : Value(f_value), Offset(c_offset) {}
  };
  typedef std::vector<SReading> TReadings;

  /// 8 readings of value 0 at ARGoS's offsets.
  CCI_FootBotBaseGroundSensor();
  virtual ~CCI_FootBotBaseGroundSensor() {}
  const TReadings& GetReadings() const { return m_tReadings; }

 protected:
  TReadings m_tReadings;
};

std::ostream& operator<<(std::ostream& c_os, const CCI_FootBotBaseGroundSensor::SReading& s_reading);
std::ostream& operator<<(std::ostream& c_os, const CCI_FootBotBaseGroundSensor::TReadings& t_readings);

}  // namespace argos
