#include "serve/experiment_inputs.h"

#include <set>

#include "lua/lua_inspect.h"

namespace essaim {

std::vector<std::string> ExperimentInputs(const Model& model, World* world) {
  std::set<std::string> inputs = {model.file};
  for (const ControllerDef& c : model.controllers)
    if (!c.script.empty()) inputs.insert(c.script);
  if (!model.loop_functions.script.empty()) inputs.insert(model.loop_functions.script);
  if (model.floor.source == FloorSource::Image && !model.floor.path.empty()) inputs.insert(model.floor.path);
  if (world) {
    std::set<int> seen;  // robots of one controller type load the same modules: ask one of them
    for (size_t i = 0; i < world->controllers.size(); ++i)
      if (world->controllers[i] && seen.insert(model.robots[i].controller).second)
        for (const std::string& f : RequiredModuleFiles(world->controllers[i]->State())) inputs.insert(f);
    for (const std::string& f : RequiredModuleFiles(world->loop_functions.State())) inputs.insert(f);
  }
  return {inputs.begin(), inputs.end()};
}

}  // namespace essaim
