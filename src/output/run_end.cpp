#include "output/run_end.h"

namespace essaim {

void EndRun(World& world, StepStatus last, RunInfo* info, Json* metrics, bool* has_metrics) {
  *has_metrics = false;
  if (last == StepStatus::Failed) {
    info->status = world.controller_errors.empty() ? "failed" : "controller_error";
    info->finished_by = "error";
  } else if (world.finished_by_loop_functions) {
    info->finished_by = "loop_functions";
  }
  std::string finish_error;
  if (last != StepStatus::Failed && !FinishRun(world, metrics, has_metrics, &finish_error)) {
    world.failure = finish_error;
    info->status = "failed";
  }
  if (info->status == "ok" && !world.controller_errors.empty()) info->status = "controller_error";
  // A run cut short may not have reached the code that reads a parameter: no guesses then.
  if (info->status == "ok" || info->status == "controller_error") world.unread_params = FindUnreadParams(world);
}

}  // namespace essaim
