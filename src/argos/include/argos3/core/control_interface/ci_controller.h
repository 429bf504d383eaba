// ARGoS's CCI_Controller (argos3/core/control_interface/ci_controller.h): a robot's
// controller. essaim runs Lua controllers only: each is a CLuaController.
#pragma once
#include <argos3/core/utility/configuration/argos_configuration.h>  // ARGoS: through base_configurable_resource.h
#include <argos3/core/utility/datatypes/datatypes.h>

#include <string>

namespace argos {

class CCI_Controller {
 public:
  virtual ~CCI_Controller() = default;
  /// The <lua_controller id="..."> this robot runs.
  const std::string& GetId() const { return m_strId; }

 protected:
  explicit CCI_Controller(const std::string& str_id) : m_strId(str_id) {}

 private:
  std::string m_strId;
};

}  // namespace argos
