// ARGoS's CCI_LEDsActuator (argos3/plugins/robots/generic/control_interface/ci_leds_actuator.h):
// the robot's LED colours (the foot-bot has 13; index 12 is the beacon). An intensity is the
// colour's alpha, as ARGoS's. Indices are checked (ARGoS's are not): one past the last throws.
#pragma once
#include <argos3/core/control_interface/ci_actuator.h>
#include <argos3/core/utility/datatypes/color.h>

#include <vector>

namespace argos {

class CCI_LEDsActuator : public CCI_Actuator {
 public:
  typedef std::vector<CColor> TSettings;

  CCI_LEDsActuator() {}
  virtual ~CCI_LEDsActuator() {}
  size_t GetNumLEDs() const { return m_tSettings.size(); }
  virtual void SetSingleColor(UInt32 un_led_number, const CColor& c_color);
  virtual void SetAllColors(const CColor& c_color);
  /// One colour per LED.
  virtual void SetAllColors(const TSettings& c_colors);
  virtual void SetSingleIntensity(UInt32 un_led_number, UInt8 un_intensity);
  virtual void SetAllIntensities(UInt8 un_intensity);

 protected:
  TSettings m_tSettings;
};

}  // namespace argos
