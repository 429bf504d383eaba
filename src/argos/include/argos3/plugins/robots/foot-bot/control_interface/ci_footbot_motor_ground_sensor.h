// ARGoS's CCI_FootBotMotorGroundSensor
// (argos3/plugins/robots/foot-bot/control_interface/ci_footbot_motor_ground_sensor.h): the 4
// ground sensors beside the wheels, Value in [0, 1] (grey level) and the sensor's Offset from
// the robot's centre in cm.
#pragma once
#include <argos3/core/control_interface/ci_sensor.h>
#include <argos3/core/utility/math/range.h>
#include <argos3/core/utility/math/vector2.h>

#include <ostream>
#include <vector>

namespace argos {

class CCI_FootBotMotorGroundSensor : public CCI_Sensor {
 public:
  struct SReading {
    Real Value;
    CVector2 Offset;
    SReading() : Value(0.0) {}
    SReading(Real f_value, const CVector2& c_offset) : Value(f_value), Offset(c_offset) {}
  };
  typedef std::vector<SReading> TReadings;

  /// 4 readings of value 0 at ARGoS's offsets.
  CCI_FootBotMotorGroundSensor();
  virtual ~CCI_FootBotMotorGroundSensor() {}
  const TReadings& GetReadings() const { return m_tReadings; }

 protected:
  TReadings m_tReadings;
};

std::ostream& operator<<(std::ostream& c_os, const CCI_FootBotMotorGroundSensor::SReading& s_reading);
std::ostream& operator<<(std::ostream& c_os, const CCI_FootBotMotorGroundSensor::TReadings& t_readings);

}  // namespace argos
