#include <argos3/core/simulator/loop_functions.h>

using namespace argos;

class CThrowingLoopFunctions : public CLoopFunctions {
 public:
  void PostStep() override {
    if (GetSpace().GetSimulationClock() == 3) THROW_ARGOSEXCEPTION("the score file is gone at tick " << 3);
  }
};

REGISTER_LOOP_FUNCTIONS(CThrowingLoopFunctions, "throwing_loop_functions")
