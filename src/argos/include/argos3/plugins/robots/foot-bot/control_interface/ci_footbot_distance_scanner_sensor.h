// ARGoS's CCI_FootBotDistanceScannerSensor
// (argos3/plugins/robots/foot-bot/control_interface/ci_footbot_distance_scanner_sensor.h):
// the rotating scanner's last readings, distance (cm; -1 too close, -2 nothing in range) by
// angle, for its short-range and long-range sensors together and apart.
#pragma once
#include <argos3/core/control_interface/ci_sensor.h>
#include <argos3/core/utility/math/angles.h>

#include <map>
#include <utility>
#include <vector>

namespace argos {

class CCI_FootBotDistanceScannerSensor : public CCI_Sensor {
 public:
  struct SReading {
    CRadians Angle;
    Real Distance;  // cm from the robot's centre
    SReading() : Angle(0.0), Distance(0.0) {}
    SReading(const CRadians& c_angle, Real f_distance) : Angle(c_angle), Distance(f_distance) {}
  };
  typedef std::vector<SReading> TReadings;
  typedef std::vector<TReadings> TLastReadings;
  typedef std::pair<CRadians, Real> TMapPair;
  typedef std::map<CRadians, Real> TReadingsMap;

  CCI_FootBotDistanceScannerSensor() : m_tReadings(4) {}
  virtual ~CCI_FootBotDistanceScannerSensor() {}
  const TReadingsMap& GetReadingsMap() { return m_tReadingsMap; }
  const TReadingsMap& GetShortReadingsMap() { return m_tShortReadingsMap; }
  const TReadingsMap& GetLongReadingsMap() { return m_tLongReadingsMap; }

 protected:
  TReadings m_tReadings;
  TLastReadings m_tLastReadings;
  TReadingsMap m_tReadingsMap;
  TReadingsMap m_tShortReadingsMap;
  TReadingsMap m_tLongReadingsMap;
};

}  // namespace argos
