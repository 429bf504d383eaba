// How a run ends, shared by `essaim run` and the Python module so both end the same run
// the same way: the loop functions' post_experiment(), the controllers' destroy(), the
// status summary.json reports. output/ only writes what this hands it.
#pragma once
#include <string>

#include "core/value.h"
#include "sim/step.h"

namespace essaim {

/// How a run ended, as summary.json reports it.
struct RunOutcome {
  std::string status = "ok";  // ok | controller_error | failed | interrupted
  std::string finished_by = "length";
};

/// End of run: loop functions' post_experiment (its table in `metrics`, `has_metrics` false
/// when it returned none), their destroy, then the controllers' destroy. False with `error`
/// when post_experiment or the loop functions' destroy fails, or a controller's destroy
/// calls os.exit.
bool FinishRun(World& world, Value* metrics, bool* has_metrics, std::string* error);

/// From the last step's status: sets outcome->status and finished_by, then (unless the run
/// failed) runs FinishRun. A FinishRun error goes to world.failure with status "failed".
/// Keeps an "interrupted" status. A run that finished (ok, controller_error) gets its
/// world.unread_params.
void EndRun(World& world, StepStatus last, RunOutcome* outcome, Value* metrics, bool* has_metrics);

}  // namespace essaim
