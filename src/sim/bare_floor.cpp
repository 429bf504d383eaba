#include "sim/bare_floor.h"

#include <time.h>

#include <chrono>
#include <memory>
#include <vector>

#include "lua/robot/bare_controller.h"
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
  // Index 0: stock allocator, 1: the run's pool. Both replay the same readings.
  std::vector<std::unique_ptr<BareController>> bare[2];
  const BareAllocator allocators[2] = {BareAllocator::Stock, BareAllocator::Pool};
  for (int a = 0; a < 2; ++a) {
    bare[a].resize(n);
    for (size_t i = 0; i < n; ++i) {
      auto& b = bare[a][i];
      b = std::make_unique<BareController>();
      if (!b->Load(model, model.robots[i], static_cast<int>(i), model.experiment.seed, error, allocators[a]))
        return false;
      // init() sees what the real init() saw: the initial readings.
      b->PushReadings(w.robots[i]);
      if (!b->CallInit(error)) return false;
    }
  }
  *out = BareFloor();
  double* wall[2] = {&out->step_seconds, &out->pool_step_seconds};
  double* cpu[2] = {&out->step_cpu_seconds, &out->pool_step_cpu_seconds};
  for (;;) {
    const StepStatus status = Step(w);
    if (status == StepStatus::Failed) {
      *error = w.failure;
      return false;
    }
    // Readings stay in RobotState after the step (the RAB payloads point at the senders'
    // applied data, unchanged until the next act): exactly what each step() saw.
    // The two allocators alternate which goes first, so neither always gets the warm cache.
    for (int k = 0; k < 2; ++k) {
      const int a = (k + static_cast<int>(out->ticks)) % 2;
      for (size_t i = 0; i < n; ++i)
        if (w.robots[i].alive && w.robots[i].controller_ok) bare[a][i]->PushReadings(w.robots[i]);
      const double cpu_start = ThreadCpuSeconds();
      const auto start = std::chrono::steady_clock::now();
      for (size_t i = 0; i < n; ++i) {
        if (!w.robots[i].alive || !w.robots[i].controller_ok) continue;
        if (!bare[a][i]->CallStep(error)) return false;
        if (a == 0) ++out->robot_steps;
      }
      *wall[a] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      *cpu[a] += ThreadCpuSeconds() - cpu_start;
    }
    ++out->ticks;
    if (status == StepStatus::Finished) return true;
  }
}

}  // namespace essaim
