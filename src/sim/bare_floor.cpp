#include "sim/bare_floor.h"

#include <time.h>

#include <chrono>
#include <memory>
#include <vector>

#include "lua/bare_controller.h"
#include "sim/step.h"

namespace essaim {

namespace {
double ThreadCpuSeconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
}  // namespace

bool MeasureBareFloor(const Model& model, BareFloor* out, std::string* error) {
  SimOptions options;
  options.threads = 1;
  auto world = World::Create(model, options, error);
  if (!world) return false;
  if (!world->failure.empty()) {  // loop-function init() failed: never stepped
    *error = world->failure;
    return false;
  }
  World& w = *world;
  const size_t n = model.robots.size();
  std::vector<std::unique_ptr<BareController>> bare(n);
  for (size_t i = 0; i < n; ++i) {
    bare[i] = std::make_unique<BareController>();
    if (!bare[i]->Load(model, model.robots[i], static_cast<int>(i), model.experiment.seed, error)) return false;
    // init() sees what the real init() saw: the initial readings.
    bare[i]->PushReadings(w.robots[i]);
    if (!bare[i]->CallInit(error)) return false;
  }
  *out = BareFloor();
  for (;;) {
    const StepStatus status = Step(w);
    if (status == StepStatus::Failed) {
      *error = w.failure;
      return false;
    }
    // Readings stay in RobotState after the step (the RAB payloads point at the senders'
    // applied data, unchanged until the next act): exactly what each step() saw.
    for (size_t i = 0; i < n; ++i)
      if (w.robots[i].alive && w.robots[i].controller_ok) bare[i]->PushReadings(w.robots[i]);
    const double cpu_start = ThreadCpuSeconds();
    const auto start = std::chrono::steady_clock::now();
    for (size_t i = 0; i < n; ++i) {
      if (!w.robots[i].alive || !w.robots[i].controller_ok) continue;
      if (!bare[i]->CallStep(error)) return false;
      ++out->robot_steps;
    }
    out->step_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out->step_cpu_seconds += ThreadCpuSeconds() - cpu_start;
    ++out->ticks;
    if (status == StepStatus::Finished) return true;
  }
}

}  // namespace essaim
