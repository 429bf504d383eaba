/* A controller and the loop functions in one library, as many course projects ship them:
 * the .argos names the library on the controller's entry and on <loop_functions>. Loaded
 * once, both share this file's statics: the loop functions count the controllers' steps. */
#include <argos3/core/control_interface/ci_controller.h>
#include <argos3/core/simulator/loop_functions.h>
#include <argos3/plugins/robots/generic/control_interface/ci_differential_steering_actuator.h>

#include <atomic>

using namespace argos;

static std::atomic<int> g_nSteps(0);

class CBothController : public CCI_Controller {
 public:
  virtual void Init(TConfigurationNode&) {
    m_pcWheels = GetActuator<CCI_DifferentialSteeringActuator>("differential_steering");
  }
  virtual void ControlStep() {
    ++g_nSteps;
    m_pcWheels->SetLinearVelocity(5, 5);
  }

 private:
  CCI_DifferentialSteeringActuator* m_pcWheels = nullptr;
};

class CBothLoopFunctions : public CLoopFunctions {
 public:
  virtual void PostExperiment() { LOG << "both: the loop functions saw " << g_nSteps.load() << " steps" << std::endl; }
};

REGISTER_CONTROLLER(CBothController, "both_controller")
REGISTER_LOOP_FUNCTIONS(CBothLoopFunctions, "both_loop_functions")
