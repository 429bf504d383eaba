// How a run ends, shared by `essaim run` and the Python module so both write the same
// summary for the same run.
#pragma once
#include "output/summary.h"
#include "sim/step.h"

namespace essaim {

/// From the last step's status: sets info->status and info->finished_by, then (unless the
/// run failed) runs FinishRun (post_experiment, controllers' destroy). A FinishRun error
/// goes to world.failure with status "failed". Keeps an "interrupted" status. A run that
/// finished (ok, controller_error) gets its world.unread_params.
void EndRun(World& world, StepStatus last, RunInfo* info, Json* metrics, bool* has_metrics);

}  // namespace essaim
