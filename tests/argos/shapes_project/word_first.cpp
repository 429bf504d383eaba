/* One of two libraries registering the same controller label (word_controller), as two
 * versions of a controller in one project do: the library loaded last gives the class. */
#include <argos3/core/control_interface/ci_controller.h>
#include <argos3/core/utility/logging/argos_log.h>

#include <cstdlib>

using namespace argos;

class CWordFirst : public CCI_Controller {
 public:
  virtual void Init(TConfigurationNode&) {
    const char* pchUnused = std::getenv("SHAPES_UNUSED_LOADED");
    LOG << GetId() << " is first; unused library loaded: " << (pchUnused ? pchUnused : "no") << std::endl;
  }
  virtual void ControlStep() {}
};

REGISTER_CONTROLLER(CWordFirst, "word_controller")
