// Calls TwinHelperWord(), defined only in libtwin_helper, which this library is not linked to.
#include <argos3/core/simulator/loop_functions.h>

#include <fstream>

using namespace argos;

extern "C" const char* TwinHelperWord();

class CNeedsHelperLoopFunctions : public CLoopFunctions {
 public:
  void Init(TConfigurationNode& t_tree) override {
    std::string output;
    GetNodeAttribute(GetNode(t_tree, "twin"), "output", output);
    std::ofstream(output) << TwinHelperWord() << "\n";
  }
};

REGISTER_LOOP_FUNCTIONS(CNeedsHelperLoopFunctions, "needs_helper_loop_functions")
