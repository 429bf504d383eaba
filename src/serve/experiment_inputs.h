// The files an experiment was read from, to watch them: a live view and `run --watch`
// start again when one of them is saved.
#pragma once
#include <string>
#include <vector>

#include "sim/world.h"

namespace essaim {

/// The .argos file, controller scripts, loop functions, floor image, and (when `world` is
/// given) every Lua module its controllers and loop functions loaded with `require`. Sorted,
/// each once.
std::vector<std::string> ExperimentInputs(const Model& model, World* world);

}  // namespace essaim
