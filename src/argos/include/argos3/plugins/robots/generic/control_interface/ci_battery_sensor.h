// ARGoS's CCI_BatterySensor (argos3/plugins/robots/generic/control_interface/ci_battery_sensor.h):
// the charge left (0 to 1) and the time left at the current rate of discharge (s; infinite
// while it does not discharge).
#pragma once
#include <argos3/core/control_interface/ci_sensor.h>

#include <limits>

namespace argos {

class CCI_BatterySensor : public CCI_Sensor {
 public:
  struct SReading {
    Real AvailableCharge;
    Real TimeLeft;
    SReading() : AvailableCharge(1.0), TimeLeft(std::numeric_limits<Real>::infinity()) {}
  };

  virtual ~CCI_BatterySensor() {}
  const SReading& GetReading() const { return m_sReading; }

 protected:
  SReading m_sReading;
};

}  // namespace argos
