// ARGoS's CCI_Actuator (argos3/core/control_interface/ci_actuator.h): what every actuator a
// C++ controller gets has. Without ARGoS's CreateLuaState: essaim's Lua controllers command
// their devices through essaim's own tables.
#pragma once
#include <argos3/core/utility/configuration/argos_configuration.h>  // ARGoS: through base_configurable_resource.h
#include <argos3/core/utility/datatypes/datatypes.h>

#include <functional>
#include <map>
#include <string>

namespace argos {

class CCI_Actuator {
 public:
  typedef std::map<std::string, CCI_Actuator*, std::less<std::string>> TMap;

  virtual ~CCI_Actuator() {}
  virtual void Init(TConfigurationNode& t_node) { (void)t_node; }
  virtual void Reset() {}
  virtual void Destroy() {}
};

}  // namespace argos
