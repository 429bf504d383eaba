// One experiment's C++ loop functions inside the ARGoS API library: the object made from
// the label, the space of entity wrappers, the random generators. The host (CppLoopFunctions)
// drives it hook by hook; each hook runs with this session current (CSimulator::GetInstance),
// and a CARGoSException, or any exception, thrown from it comes back as `error`.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "argos/argos_world.h"

namespace ticpp {
class Element;
}

namespace essaim {

enum class ArgosHook { Reset, Destroy, PreStep, PostStep, PostExperiment };

/// The labels registered so far by loaded libraries, each with the API version it was built
/// for and the library (real path) that registered it.
struct ArgosRegistration {
  std::string label;
  int api_version = 0;
  std::string library;
};
std::vector<ArgosRegistration> ArgosRegisteredLabels();
int ArgosApiVersion();
/// Appends to `into` the LOG/LOGERR lines written outside any hook since the last call
/// ("<O or E><text>\n" each) and forgets them.
void ArgosTakeOrphanLog(std::string* into);

class ArgosSession {
 public:
  explicit ArgosSession(ArgosWorld* world);
  ~ArgosSession();
  ArgosSession(const ArgosSession&) = delete;
  ArgosSession& operator=(const ArgosSession&) = delete;

  /// Makes the loop functions registered as `label` by one of `libraries` (real paths; the
  /// last that does, as ARGoS's factory); false with `error` when none does, one registers it
  /// twice, or it was built for another API version.
  bool Create(const std::vector<std::string>& libraries, const std::string& label, std::string* error);
  bool Init(ticpp::Element& tree, std::string* error);
  bool Run(ArgosHook hook, std::string* error);
  bool IsExperimentFinished(bool* finished, std::string* error);
  bool FloorColor(double x, double y, ArgosRgb* color, std::string* error);
  /// Whether the last hook that failed threw a configuration error (a bad .argos element).
  bool LastErrorIsConfiguration() const;

  struct State;

 private:
  std::unique_ptr<State> state_;
};

}  // namespace essaim
