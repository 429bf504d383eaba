#include "argos/cpp_loop_functions.h"

#include <argos3/core/utility/configuration/argos_configuration.h>

#include <cstdlib>
#include <cstring>

#include "argos/argos_session.h"
#include "argos/config_tree.h"
#include "argos/store_world.h"

namespace essaim {

CppLoopFunctions::CppLoopFunctions() = default;

// Destroy() ran at the end of the run (sim/run_end), as ARGoS calls it; here the loop
// functions are only deleted (after an error, as ARGoS, without Destroy()).
CppLoopFunctions::~CppLoopFunctions() = default;

bool CppLoopFunctions::Load(const Model& model, ArgosHost* host, std::string* error) {
  const LoopFunctionsDef& def = model.loop_functions;
  // As ARGoS's factory: the label among the experiment's libraries, the last that registers it.
  if (host->Session().Create(host->Libraries(), def.label, error)) {
    model_ = &model;
    host_ = host;
    return true;
  }
  *error = def.loc.file + ":" + std::to_string(def.loc.line) + ": <loop_functions>: " + *error;
  if (def.library.empty() && !std::getenv("ARGOS_PLUGIN_PATH"))
    *error += " (no library=\"...\" given and ARGOS_PLUGIN_PATH is not set)";
  return false;
}

bool CppLoopFunctions::Call(const char* hook, std::string* error) {
  if (!std::strcmp(hook, "init")) {
    ticpp::Element tree = ConfigurationTree(model_->loop_functions.xml, model_->loop_functions.loc.file);
    return host_->Session().Init(tree, error);
  }
  static const std::pair<const char*, ArgosHook> hooks[] = {{"pre_step", ArgosHook::PreStep},
                                                            {"post_step", ArgosHook::PostStep},
                                                            {"reset", ArgosHook::Reset},
                                                            {"destroy", ArgosHook::Destroy},
                                                            {"post_experiment", ArgosHook::PostExperiment}};
  for (const auto& h : hooks)
    if (!std::strcmp(hook, h.first)) return host_->Session().Run(h.second, error);
  *error = std::string("loop functions: no hook '") + hook + "'";
  return false;
}

bool CppLoopFunctions::IsExperimentFinished(bool* finished, std::string* error) {
  return host_->Session().IsExperimentFinished(finished, error);
}

bool CppLoopFunctions::FloorColor(double x, double y, Color* out, std::string* error) {
  ArgosRgb rgb;
  if (!host_->Session().FloorColor(x, y, &rgb, error)) return false;
  *out = Color{rgb.r, rgb.g, rgb.b, 255};
  return true;
}

bool CppLoopFunctions::LastErrorIsConfiguration() const { return host_->Session().LastErrorIsConfiguration(); }
bool CppLoopFunctions::TakeFloorChanged() { return host_->World().TakeFloorChanged(); }
std::string& CppLoopFunctions::LogBuffer() { return host_->World().LogBuffer(); }

}  // namespace essaim
