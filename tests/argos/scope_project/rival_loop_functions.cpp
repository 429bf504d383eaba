// Another class under the twin's label: with `label` alone, the library loaded last wins, as
// in ARGoS's factory.
#include <argos3/core/simulator/loop_functions.h>

#include <fstream>

using namespace argos;

class CRivalLoopFunctions : public CLoopFunctions {
 public:
  void Init(TConfigurationNode& t_tree) override {
    std::string output;
    GetNodeAttribute(GetNode(t_tree, "twin"), "output", output);
    std::ofstream(output) << "rival\n";
  }
};

REGISTER_LOOP_FUNCTIONS(CRivalLoopFunctions, "twin_loop_functions")
