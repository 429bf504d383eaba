#include "sim/run_end.h"

#include "sim/loop_hooks.h"
#include "sim/stepping.h"

namespace essaim {

bool FinishRun(World& w, Value* metrics, bool* has_metrics, std::string* error) {
  bool ok = LoopPostExperiment(w, metrics, has_metrics, error);
  FlushLoopLog(w);
  // ARGoS destroys the loop functions first, then the space with its controllers (and
  // not at all after an error: its main() catches the exception and returns).
  if (ok) ok = DestroyLoopFunctions(w, error);
  for (size_t i = 0; i < w.controllers.size(); ++i) {
    std::string err;
    const SteppingScope stepping(static_cast<int>(i), "Destroy");
    if (w.robots[i].controller_ok && !w.controllers[i]->Destroy(&err)) {
      w.controller_errors.push_back({w.model.robots[i].id, w.tick, err});
      if (w.controllers[i]->ExitCalled() && ok) {
        ok = false;
        *error = err;
      }
    }
    FlushLog(w, w.controllers[i]->LogBuffer(), static_cast<int>(i));
  }
  return ok;
}

void EndRun(World& world, StepStatus last, RunOutcome* outcome, Value* metrics, bool* has_metrics) {
  *has_metrics = false;
  if (last == StepStatus::Failed) {
    outcome->status = world.controller_errors.empty() ? "failed" : "controller_error";
    outcome->finished_by = "error";
  } else if (world.finished_by_loop_functions) {
    outcome->finished_by = "loop_functions";
  }
  std::string finish_error;
  if (last != StepStatus::Failed && !FinishRun(world, metrics, has_metrics, &finish_error)) {
    world.failure = finish_error;
    outcome->status = "failed";
  }
  if (outcome->status == "ok" && !world.controller_errors.empty()) outcome->status = "controller_error";
  // A run cut short may not have reached the code that reads a parameter: no guesses then.
  if (outcome->status == "ok" || outcome->status == "controller_error") world.unread_params = FindUnreadParams(world);
}

}  // namespace essaim
