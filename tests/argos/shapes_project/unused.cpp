/* A library declared in <controllers> that no robot uses: ARGoS loads it all the same, and
 * its static initialisers run (here: they leave a mark the other controllers read). */
#include <argos3/core/control_interface/ci_controller.h>

#include <cstdlib>

using namespace argos;

namespace {
struct SMark {
  SMark() { setenv("SHAPES_UNUSED_LOADED", "yes", 1); }
} g_sMark;
}  // namespace

class CUnused : public CCI_Controller {
 public:
  virtual void Init(TConfigurationNode&) {}
  virtual void ControlStep() {}
};

REGISTER_CONTROLLER(CUnused, "unused_controller")
