// ARGoS's CControllableEntity (argos3/core/simulator/entity/controllable_entity.h): the
// controller component of a robot.
#pragma once
#include <argos3/core/control_interface/ci_controller.h>
#include <argos3/core/simulator/entity/entity.h>
#include <argos3/core/utility/math/vector3.h>  // ARGoS: through ray3.h

#include <memory>

namespace argos {

class CControllableEntity : public CEntity {
 public:
  CControllableEntity(CEntity* pc_parent, const std::string& str_id, const std::string& str_controller_id)
      : CEntity(pc_parent, str_id), m_strControllerId(str_controller_id) {}
  ~CControllableEntity() override;
  std::string GetTypeDescription() const override { return "controller"; }
  /// The robot's controller: its C++ controller, or a CLuaController for a Lua one; throws
  /// before the robot is in the space.
  CCI_Controller& GetController();

 private:
  std::string m_strControllerId;
  CCI_Controller* m_pcController = nullptr;  // a Lua controller's wrapper, made at the first GetController
};

}  // namespace argos
