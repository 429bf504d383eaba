// The .argos loader with --set overrides, then the world it describes for a few ticks.
// Input: lines "set PATH=VALUE" first (any number), then the XML text. The file is placed
// in tests/fuzz/data/, so script="fuzz.lua" and <floor path="floor.png"> resolve; scripts
// run sandboxed (no io/os) under a small budget, so a fuzzed path to some other Lua file
// can neither touch the machine nor spin.
#include <cstdint>
#include <memory>
#include <string>

#include "core/error_list.h"
#include "model/xml_loader.h"
#include "sim/step.h"
#include "sim/world.h"

using namespace essaim;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  LoadOptions options;
  options.working_dir = ESSAIM_FUZZ_DATA;
  while (text.compare(0, 4, "set ") == 0) {
    size_t end = text.find('\n');
    if (end == std::string::npos) break;
    options.overrides.push_back(text.substr(4, end - 4));
    text.erase(0, end + 1);
  }
  ErrorList errors, warnings;
  std::unique_ptr<Model> model =
      LoadExperimentText(text, std::string(ESSAIM_FUZZ_DATA) + "/fuzz.argos", options, &errors, &warnings);
  errors.Format();
  warnings.Format();
  // Stepping thousands of robots is slow, not wrong: the loader alone is fuzzed for those.
  if (!model || model->robots.size() > 64 || model->obstacles.size() > 256) return 0;
  SimOptions sim;
  sim.threads = 1;
  sim.lua.sandbox = true;
  sim.lua.memory_limit = size_t{16} << 20;
  sim.lua.instruction_limit = sim.lua.setup_instruction_limit = 1000000;
  std::string error;
  std::unique_ptr<World> world = World::Create(*model, sim, &error);
  if (!world) return 0;
  for (int t = 0; t < 3; ++t)
    if (Step(*world) != StepStatus::Running) break;
  return 0;
}
