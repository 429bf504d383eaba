/* A foot-bot controller of the same old-style project: counts its steps and says so at the
   end, as controllers of that era print from Destroy(). */
#include <argos3/core/control_interface/ci_controller.h>
#include <argos3/core/utility/logging/argos_log.h>
#include <argos3/plugins/robots/generic/control_interface/ci_differential_steering_actuator.h>

using namespace argos;

class COldModulesController : public CCI_Controller {
 public:
  COldModulesController() : m_pcWheels(NULL), m_unSteps(0) {}
  virtual void Init(TConfigurationNode& t_node) {
    m_pcWheels = GetActuator<CCI_DifferentialSteeringActuator>("differential_steering");
    GetNodeAttributeOrDefault(t_node, "speed", m_fSpeed, 4.0);
  }
  virtual void ControlStep() {
    ++m_unSteps;
    m_pcWheels->SetLinearVelocity(m_fSpeed, m_fSpeed);
  }
  virtual void Destroy() { LOG << "old modules controller: " << GetId() << " steps " << m_unSteps << std::endl; }

 private:
  CCI_DifferentialSteeringActuator* m_pcWheels;
  Real m_fSpeed;
  UInt32 m_unSteps;
};

REGISTER_CONTROLLER(COldModulesController, "old_modules_controller")
