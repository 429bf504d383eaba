// Writes TWIN_WORD, through a virtual function, to <twin output="...">. Two builds of this
// file with other words define the same class under the same label.
#include <argos3/core/simulator/loop_functions.h>

#include <fstream>

using namespace argos;

class CTwinLoopFunctions : public CLoopFunctions {
 public:
  void Init(TConfigurationNode& t_tree) override;
  virtual std::string Word() const;
};

std::string CTwinLoopFunctions::Word() const { return TWIN_WORD; }

void CTwinLoopFunctions::Init(TConfigurationNode& t_tree) {
  std::string output;
  GetNodeAttribute(GetNode(t_tree, "twin"), "output", output);
  std::ofstream(output) << Word() << "\n";
}

REGISTER_LOOP_FUNCTIONS(CTwinLoopFunctions, "twin_loop_functions")
#ifdef TWIN_TWICE
REGISTER_LOOP_FUNCTIONS(CTwinLoopFunctions, "twin_loop_functions")
#endif
