// ARGoS's CCI_FootBotLightSensor
// (argos3/plugins/robots/foot-bot/control_interface/ci_footbot_light_sensor.h): the 24 light
// readings, Value in [0, 1] and the sensor's Angle in the robot's frame.
#pragma once
#include <argos3/core/control_interface/ci_sensor.h>
#include <argos3/core/utility/math/angles.h>

#include <ostream>
#include <vector>

namespace argos {

class CCI_FootBotLightSensor : public CCI_Sensor {
 public:
  struct SReading {
    Real Value;
    CRadians Angle;
    SReading() : Value(0.0) {}
    SReading(Real f_value, const CRadians& c_angle) : Value(f_value), Angle(c_angle) {}
  };
  typedef std::vector<SReading> TReadings;

  /// 24 readings of value 0, at ARGoS's angles (pi/24 + k pi/12, signed).
  CCI_FootBotLightSensor();
  virtual ~CCI_FootBotLightSensor() {}
  const TReadings& GetReadings() const { return m_tReadings; }

 protected:
  TReadings m_tReadings;
};

std::ostream& operator<<(std::ostream& c_os, const CCI_FootBotLightSensor::SReading& s_reading);
std::ostream& operator<<(std::ostream& c_os, const CCI_FootBotLightSensor::TReadings& t_readings);

}  // namespace argos
