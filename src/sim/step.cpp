#include "sim/step.h"

#include <chrono>

#include "devices/devices.h"
#include "sim/error_groups.h"
#include "sim/thread_pool.h"

namespace essaim {

namespace {
using Clock = std::chrono::steady_clock;
double Seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

// The media stage's per-device RAB work on the pool, one slot per thread (results do not
// depend on the slot count: devices/media.cpp).
SlotRunner MediaRunner(World& w) {
  SlotRunner r;
  r.slots = w.pool->Size();
  r.pool = w.pool.get();
  r.run = [](void* pool, SlotRunner::Job job, void* ctx) {
    ThreadPool& p = *static_cast<ThreadPool*>(pool);
    auto each = [&](int begin, int end) {
      for (int slot = begin; slot < end; ++slot) job(ctx, slot);
    };
    p.ParallelFor(p.Size(), each);
  };
  return r;
}

// The "scene changed" notification: loop functions added, removed, moved or recoloured
// entities, so the media (occluder grids, lit LEDs) are rebuilt before anything senses.
// Layout changes resize the media's buffers; that allocates, but only on such a tick.
void RefreshMediaIfSceneChanged(World& w) {
  if (!w.entities.changed()) return;
  if (w.entities.layout_changed()) w.media.ready = false;
  UpdateMedia(w.model, w.physics, w.robots, &w.media, MediaRunner(w));
  w.entities.ClearChanged();
}

bool LoopCall(World& w, const char* hook) {
  std::string err;
  if (!w.loop_functions.Call(hook, &err)) {
    w.failure = err;
    return false;
  }
  return true;
}
}  // namespace

bool LengthReached(const World& w) {
  return w.model.experiment.length_ticks > 0 && w.tick >= w.model.experiment.length_ticks;
}

StepStatus Step(World& w) {
  const Model& m = w.model;
  const int n = static_cast<int>(w.robots.size());
  const double dt = m.experiment.TickLength();
  ++w.tick;
  w.loop_functions.SetTick(w.tick);

  auto t0 = Clock::now();
  // Each robot's wheels, scanner, LEDs and RAB payload: its own state and servo only.
  auto act = [&](int begin, int end) {
    for (int i = begin; i < end; ++i) ActRobotOwnState(m, m.robots[i], w.robots[i], w.physics);
  };
  // ~0.1 µs a robot against ~5-10 µs to wake the pool: threads pay off from a few hundred.
  // Balanced: the tick does not wait for a worker slow to wake (it finds nothing left).
  constexpr int kParallelActMin = 256;
  if (n >= kParallelActMin) w.pool->ParallelForBalanced(n, act);
  else act(0, n);
  for (int i = 0; i < n; ++i) ActRobotJoints(m, m.robots[i], w.robots[i], w.physics);
  auto t1 = Clock::now();
  w.physics.Step(dt, m.physics.iterations);
  for (int i = 0; i < n; ++i) UpdateRobotComponents(m, m.robots[i], w.robots[i], w.physics, w.tick);
  auto t2 = Clock::now();
  if (w.entities.layout_changed()) w.media.ready = false;  // changed by post_step or init
  w.entities.ClearChanged();
  UpdateMedia(m, w.physics, w.robots, &w.media, MediaRunner(w));
  auto t3 = Clock::now();
  bool ok = LoopCall(w, "pre_step");
  RefreshMediaIfSceneChanged(w);
  FlushLog(w, w.loop_functions.LogBuffer(), kLogLoopFunctions);
  auto t4 = Clock::now();
  w.times.act += Seconds(t0, t1);
  w.times.physics += Seconds(t1, t2);
  w.times.media += Seconds(t2, t3);
  w.times.loop_functions += Seconds(t3, t4);
  if (!ok) return StepStatus::Failed;

  // Sense + control: robots are independent here (each writes only its own state).
  const SenseContext ctx{m, w.physics, w.media, w.floor, w.robots, w.tick, dt};
  auto work = [&](int begin, int end) {
    World::ChunkTimes local;
    for (int i = begin; i < end; ++i) {
      RobotState& r = w.robots[i];
      if (!r.alive || !r.controller_ok) continue;
      auto a = Clock::now();
      SenseRobot(ctx, m.robots[i], r);
      LuaController& c = *w.controllers[i];
      const bool pushed = c.PushReadings(&w.pending_errors[i]);
      auto b = Clock::now();
      if (!pushed || !c.CallStep(&w.pending_errors[i])) {
        r.controller_ok = false;
        // The robot stops: zero wheels from the next act on (spec: never stepped again).
        r.cmd.wheel_left = r.cmd.wheel_right = 0;
        r.cmd.wheels_new = true;
      }
      auto e = Clock::now();
      local.sense += Seconds(a, b);
      local.control += Seconds(b, e);
    }
    // Ranges are disjoint, so the range's first robot names its slot: no shared writes.
    w.chunk_times[static_cast<size_t>(begin)] = local;
  };
  // Balanced: robots cost different amounts (crowds, dead ones) and a thread may lose its
  // core for a while; measured at 2 threads, equal static chunks differed by 1.6-2.1% in
  // thread CPU time per tick (the faster thread then idles at the barrier).
  w.pool->ParallelForBalanced(n, work);
  for (World::ChunkTimes& t : w.chunk_times) {
    w.times.sense += t.sense;
    w.times.control += t.control;
    t = World::ChunkTimes();
  }

  auto t5 = Clock::now();
  bool failed = false;
  const size_t errors_before = w.controller_errors.size();
  for (int i = 0; i < n; ++i) {
    FlushLog(w, w.controllers[i]->LogBuffer(), static_cast<int>(i));
    if (!w.pending_errors[i].empty()) {
      w.controller_errors.push_back({m.robots[i].id, w.tick, w.pending_errors[i]});
      w.pending_errors[i].clear();
      if (w.options.strict || w.controllers[i]->ExitCalled()) {
        w.failure = w.controller_errors.back().message;
        failed = true;
      }
    }
  }
  // This tick's errors, identical ones grouped (after the logs, as before).
  if (w.options.log_sink && w.controller_errors.size() > errors_before)
    for (const std::string& text : GroupControllerErrors(w.controller_errors, errors_before)) w.options.log_sink('E', text, {w.tick, kLogHost});
  if (failed) return StepStatus::Failed;
  ok = LoopCall(w, "post_step");
  bool finished = false;
  if (ok) {
    std::string err;
    ok = w.loop_functions.IsExperimentFinished(&finished, &err);
    if (!ok) w.failure = err;
  }
  FlushLog(w, w.loop_functions.LogBuffer(), kLogLoopFunctions);
  w.times.loop_functions += Seconds(t5, Clock::now());
  if (!ok) return StepStatus::Failed;
  if (finished) {
    w.finished_by_loop_functions = true;
    return StepStatus::Finished;
  }
  return LengthReached(w) ? StepStatus::Finished : StepStatus::Running;
}

}  // namespace essaim
