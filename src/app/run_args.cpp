#include "app/run_args.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <limits>
#include <vector>

#include "app/cli_support.h"
#include "app/set_file.h"

namespace essaim {

void AddExperimentOptions(CLI::App* sub, RunArgs* r) {
  sub->add_option("FILE.argos", r->file, "the ARGoS experiment file")->required();
  sub->add_option("--ticks", r->ticks, "run exactly N ticks, N >= 1 (overrides the experiment length)")
      ->type_name("N")
      ->check(IntegerIn(1, kMaxTicks, "0 would mean no limit; for that set framework.experiment.length=0"));
  sub->add_option("--seed", r->seed, "random seed, >= 0 (overrides random_seed)")
      ->type_name("S")
      ->check(IntegerIn(0, std::numeric_limits<long long>::max()));
  sub->add_option("--threads", r->threads, "threads for sense + control, 1 to 1024 (overrides <system threads>)")
      ->type_name("N")
      ->check(IntegerIn(1, kMaxThreads, "1 runs everything on the main thread"));
  sub->add_option("--set", r->load.overrides,
                  "override an XML attribute (repeatable), e.g. controllers.ctrl.params.speed=20")
      ->type_name("PATH=VALUE")
      ->allow_extra_args(false);
  sub->add_option("--set-file", r->set_file,
                  "a JSON object {\"PATH\": value, ...} of overrides, applied before the --set ones")
      ->type_name("FILE.json");
}

// --set-file's entries first, so a --set on the command line wins over the file.
bool ApplyOptions(RunArgs* r, std::string* error) {
  if (r->ticks) r->load.ticks = static_cast<uint64_t>(*r->ticks);
  if (r->seed) r->load.seed = static_cast<uint64_t>(*r->seed);
  if (r->threads) r->load.threads = static_cast<int>(*r->threads);
  r->load.strict = r->strict;
  if (r->set_file.empty()) return true;
  std::vector<std::string> from_file;
  if (!ReadOverridesFile(r->set_file, &from_file, error)) return false;
  r->load.overrides.insert(r->load.overrides.begin(), from_file.begin(), from_file.end());
  return true;
}

std::unique_ptr<Model> LoadOrReport(const RunArgs& r, std::string* message) {
  ErrorList errors, warnings;
  auto model = LoadExperimentFile(r.file, r.load, &errors, &warnings);
  for (const InputError& w : warnings.Items()) {  // --quiet keeps them: a sweep must hear of a typo
    ErrorList one;
    one.Add(w.file, w.line, w.element, "warning: " + w.message);
    std::fputs(one.Format().c_str(), stderr);
  }
  if (!model) std::fputs(errors.Format().c_str(), stderr);
  if (!model && message) {
    *message = errors.Format();
    while (!message->empty() && message->back() == '\n') message->pop_back();
  }
  return model;
}

LuaOptions WatchdogOptions(const Model& m, const RunArgs& r) {
  LuaOptions o;
  o.sandbox = r.sandbox;
  if (r.sandbox) {
    o.memory_limit = size_t{64} << 20;
    o.instruction_limit = o.setup_instruction_limit = kDefaultStepBudget;
  }
  long long budget = r.lua_budget >= 0 ? r.lua_budget : m.experiment.lua_budget;
  long long init_budget = r.lua_init_budget >= 0 ? r.lua_init_budget : m.experiment.lua_init_budget;
  long long mib = r.lua_memory_mib >= 0 ? r.lua_memory_mib : m.experiment.lua_memory_mib;
  if (budget >= 0) {
    o.instruction_limit = budget;
    // A step budget set above the setup calls' (or unlimited) lifts theirs with it.
    if (budget == 0 || (o.setup_instruction_limit > 0 && budget > o.setup_instruction_limit))
      o.setup_instruction_limit = budget;
  }
  if (init_budget >= 0) o.setup_instruction_limit = init_budget;
  if (mib >= 0) o.memory_limit = static_cast<size_t>(mib) << 20;
  if (r.lua_seconds >= 0) o.wall_seconds = r.lua_seconds;
  return o;
}

}  // namespace essaim
