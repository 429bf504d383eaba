// `essaim run`'s one run and its options, shared with `essaim debug` (cmd_debug.cpp), which
// runs the same World, outputs and summary with its hooks in between.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "app/run_args.h"
#include "output/summary.h"
#include "sim/world.h"

namespace CLI {
class App;
}

namespace essaim {

class RunSession;

/// What a caller adds to the run (all optional).
struct RunHooks {
  /// Changes the World's options before it is made (log lines, Lua options).
  std::function<void(SimOptions*)> options;
  /// Called before each tick (at the boundary before tick world.tick + 1); false ends the run
  /// there as finished.
  std::function<bool(World&)> before_tick;
  /// What stops the run (a script that does not load, a loop function's error), also said
  /// on stderr.
  std::function<void(const std::string&)> error;
  /// Called once the run ended, before the outputs are written.
  std::function<void(RunInfo*)> finishing;
};

/// The run options' values that need a step after parsing.
struct RunOptionValues {
  double budget = -1, init_budget = -1;
};

/// `essaim run`'s options (the experiment, --out, --seed, --set, --record, the Lua limits...).
void AddRunOptions(CLI::App* sub, RunArgs* r, RunOptionValues* v);
/// After parsing: the budgets and --record into `r`.
void FinishRunOptions(CLI::App* sub, RunArgs* r, const RunOptionValues& v);

/// One run as `essaim run` does it; the exit code. `inputs` receives the files it read.
int RunExperiment(RunSession& session, RunArgs& r, std::vector<std::string>* inputs, const RunHooks* hooks);

}  // namespace essaim
