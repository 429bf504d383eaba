// ARGoS's CCI_Sensor (argos3/core/control_interface/ci_sensor.h): what every sensor a C++
// controller gets has. Without ARGoS's CreateLuaState/ReadingsToLuaState: essaim's Lua
// controllers read their devices through essaim's own tables.
#pragma once
#include <argos3/core/utility/configuration/argos_configuration.h>  // ARGoS: through base_configurable_resource.h
#include <argos3/core/utility/datatypes/datatypes.h>

#include <functional>
#include <map>
#include <string>

namespace argos {

class CCI_Sensor {
 public:
  typedef std::map<std::string, CCI_Sensor*, std::less<std::string>> TMap;

  virtual ~CCI_Sensor() {}
  virtual void Init(TConfigurationNode& t_node) { (void)t_node; }
  virtual void Reset() {}
  virtual void Destroy() {}
  virtual void Enable() { m_bEnabled = true; }
  virtual void Disable() { m_bEnabled = false; }
  bool IsEnabled() const { return m_bEnabled; }
  bool IsDisabled() const { return !m_bEnabled; }

 private:
  bool m_bEnabled = false;  // ARGoS's: off until the sensor (or the controller) enables it
};

}  // namespace argos
