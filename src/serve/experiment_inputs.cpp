#include "serve/experiment_inputs.h"

#include <set>

#include "core/input_files.h"

namespace essaim {

// The list summary.json gives (the world's inputs, `require`d modules included), so what is
// watched and what a run's identity hashes are the same files.
std::vector<std::string> ExperimentInputs(const Model& model, World* world) {
  InputFiles model_only;
  if (!world) ListModelInputs(model, &model_only);
  const InputFiles& files = world ? *world->inputs : model_only;
  std::set<std::string> paths;
  for (const InputFile& f : files.List()) paths.insert(f.path);
  return {paths.begin(), paths.end()};
}

}  // namespace essaim
