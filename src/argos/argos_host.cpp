#include "argos/argos_host.h"

#include "argos/argos_session.h"
#include "argos/plugin_libraries.h"
#include "argos/store_world.h"

namespace essaim {

ArgosHost::ArgosHost() = default;
ArgosHost::~ArgosHost() = default;

bool ArgosHost::Needed(const Model& model) {
  if (model.loop_functions.Cpp()) return true;
  for (const ControllerDef& c : model.controllers)
    if (c.Cpp()) return true;
  return false;
}

namespace {
// As ARGoS: every library of ARGOS_PLUGIN_PATH is there from the start (needed here only when
// a label comes without a library), then <controllers>' in order, then <loop_functions>'.
std::vector<std::string> ExperimentLibraries(const Model& model) {
  bool label_alone = model.loop_functions.Cpp() && model.loop_functions.library.empty();
  for (const ControllerDef& c : model.controllers) label_alone |= c.Cpp() && c.library.empty();
  std::vector<std::string> paths;
  if (label_alone) paths = PluginPathLibraries();
  for (const ControllerDef& c : model.controllers)
    if (!c.library.empty()) paths.push_back(c.library);
  if (!model.loop_functions.library.empty()) paths.push_back(model.loop_functions.library);
  return paths;
}

// "FILE:LINE: <element>: " of the entry naming the library `error` is about, or "FILE: ".
std::string WhereLibraryIs(const Model& model, const std::string& error) {
  for (const ControllerDef& c : model.controllers)
    if (!c.library.empty() && error.find(c.library) != std::string::npos)
      return c.loc.file + ":" + std::to_string(c.loc.line) + ": <" + c.label + " id=\"" + c.id + "\">: ";
  const LoopFunctionsDef& lf = model.loop_functions;
  if (!lf.library.empty() && error.find(lf.library) != std::string::npos)
    return lf.loc.file + ":" + std::to_string(lf.loc.line) + ": <loop_functions>: ";
  return model.file + ": ";
}
}  // namespace

bool ArgosHost::Load(const Model& model, EntityStore* entities,
                     std::vector<std::unique_ptr<RobotController>>* controllers, std::string* error) {
  if (!LoadArgosLibraries(ExperimentLibraries(model), &libraries_, error))
    return *error = WhereLibraryIs(model, *error) + *error, false;
  world_ = std::make_unique<StoreWorld>(model, entities, controllers);
  session_ = std::make_unique<ArgosSession>(world_.get());
  return true;
}

void ArgosHost::SetTick(uint64_t tick) { world_->SetTick(tick); }

}  // namespace essaim
