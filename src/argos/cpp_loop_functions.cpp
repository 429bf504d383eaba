#include "argos/cpp_loop_functions.h"

#include <argos3/core/utility/configuration/argos_configuration.h>

#include <cstdlib>
#include <cstring>

#include "argos/argos_session.h"
#include "argos/plugin_libraries.h"
#include "argos/store_world.h"

namespace essaim {

namespace {
ticpp::Element ToElement(const XmlNode& node, const std::string& file) {
  ticpp::Element element(node.name);
  element.SetLocation(file, node.line);
  for (const auto& attribute : node.attributes) element.SetAttribute(attribute.first, attribute.second);
  element.SetText(node.text);
  for (const XmlNode& child : node.children) element.Children().push_back(ToElement(child, file));
  return element;
}
}  // namespace

CppLoopFunctions::CppLoopFunctions() = default;

// Destroy() ran at the end of the run (sim/run_end), as ARGoS calls it; here the loop
// functions are only deleted (after an error, as ARGoS, without Destroy()).
CppLoopFunctions::~CppLoopFunctions() = default;

bool CppLoopFunctions::Load(const Model& model, EntityStore* entities,
                            std::vector<std::unique_ptr<LuaController>>* controllers, std::string* error) {
  const LoopFunctionsDef& def = model.loop_functions;
  const std::string where = def.loc.file + ":" + std::to_string(def.loc.line) + ": <loop_functions>: ";
  // As ARGoS: the library named, or every library of ARGOS_PLUGIN_PATH; the label is looked
  // up among these only, never among another experiment's.
  std::vector<std::string> libraries;
  if (!LoadLoopFunctionLibraries(def.library.empty() ? PluginPathLibraries() : std::vector<std::string>{def.library},
                                 &libraries, error))
    return *error = where + *error, false;
  model_ = &model;
  world_ = std::make_unique<StoreWorld>(model, entities, controllers);
  session_ = std::make_unique<ArgosSession>(world_.get());
  if (session_->Create(libraries, def.label, error)) return true;
  *error = where + *error;
  if (def.library.empty() && !std::getenv("ARGOS_PLUGIN_PATH"))
    *error += " (no library=\"...\" given and ARGOS_PLUGIN_PATH is not set)";
  session_.reset();
  return false;
}

void CppLoopFunctions::SetTick(uint64_t tick) { world_->SetTick(tick); }

bool CppLoopFunctions::Call(const char* hook, std::string* error) {
  if (!std::strcmp(hook, "init")) {
    ticpp::Element tree = ToElement(model_->loop_functions.xml, model_->loop_functions.loc.file);
    return session_->Init(tree, error);
  }
  static const std::pair<const char*, ArgosHook> hooks[] = {{"pre_step", ArgosHook::PreStep},
                                                            {"post_step", ArgosHook::PostStep},
                                                            {"reset", ArgosHook::Reset},
                                                            {"destroy", ArgosHook::Destroy},
                                                            {"post_experiment", ArgosHook::PostExperiment}};
  for (const auto& h : hooks)
    if (!std::strcmp(hook, h.first)) return session_->Run(h.second, error);
  *error = std::string("loop functions: no hook '") + hook + "'";
  return false;
}

bool CppLoopFunctions::IsExperimentFinished(bool* finished, std::string* error) {
  return session_->IsExperimentFinished(finished, error);
}

bool CppLoopFunctions::FloorColor(double x, double y, Color* out, std::string* error) {
  ArgosRgb rgb;
  if (!session_->FloorColor(x, y, &rgb, error)) return false;
  *out = Color{rgb.r, rgb.g, rgb.b, 255};
  return true;
}

bool CppLoopFunctions::LastErrorIsConfiguration() const { return session_->LastErrorIsConfiguration(); }
bool CppLoopFunctions::TakeFloorChanged() { return world_->TakeFloorChanged(); }
std::string& CppLoopFunctions::LogBuffer() { return world_->LogBuffer(); }

}  // namespace essaim
