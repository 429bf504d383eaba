#include "sim/step.h"

#include <algorithm>
#include <chrono>

#include "devices/devices.h"
#include "sim/error_groups.h"
#include "sim/loop_hooks.h"
#include "sim/stepping.h"
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
  if (!CallLoopHook(w, hook, &err) || !RedrawFloorIfChanged(w, &err)) {
    w.failure = err;
    return false;
  }
  return true;
}

// ---- the stages, in the order Step runs them

void BeginTick(World& w) {
  ++w.tick;
  w.robot_steps += w.robots.size();
  SetLoopTick(w);
}

// ~0.1 µs a robot against ~5-10 µs to wake the pool: per-robot passes this cheap pay off on
// threads from a few hundred robots. Balanced: the tick does not wait for a worker slow to
// wake (it finds nothing left).
constexpr int kParallelCheapMin = 256;

// `pass(begin, end)` over every robot: on the pool when there are enough robots to pay for
// waking it, else here.
template <typename Pass>
void ForEachRobotCheap(World& w, Pass& pass) {
  const int n = static_cast<int>(w.robots.size());
  if (n >= kParallelCheapMin)
    w.pool->ParallelForBalanced(n, pass);
  else
    pass(0, n);
}

// Commands the controllers set last tick. First each robot's wheels, scanner, LEDs and RAB
// payload (its own state and servo only: any thread), then gripper and turret, which make
// joints in the one physics world (one thread, robot order).
void ActStage(World& w) {
  const Model& m = w.model;
  const int n = static_cast<int>(w.robots.size());
  auto act = [&](int begin, int end) {
    for (int i = begin; i < end; ++i) ActRobotOwnState(m, m.robots[i], w.robots[i], w.physics);
  };
  ForEachRobotCheap(w, act);
  for (int i = 0; i < n; ++i) ActRobotJoints(m, m.robots[i], w.robots[i], w.physics);
}

// The physics regions' steps on the pool, one region at a time per thread (each region's
// world is its own; results do not depend on who steps it).
PhysicsRunner PhysicsRegionRunner(World& w) {
  PhysicsRunner r;
  r.pool = w.pool.get();
  r.run = [](void* pool, int n, PhysicsRunner::Job job, void* ctx) {
    auto each = [&](int begin, int end) {
      for (int item = begin; item < end; ++item) job(ctx, item);
    };
    static_cast<ThreadPool*>(pool)->ParallelForBalanced(n, each);
  };
  return r;
}

// One Box2D step of `iterations` sub-steps, then what follows from the motion (battery
// discharge, scanner rotation).
void PhysicsStage(World& w) {
  const Model& m = w.model;
  w.physics.Step(m.experiment.TickLength(), m.physics.iterations, PhysicsRegionRunner(w));
  // Each robot's own battery and scanner, from its body's pose: any thread.
  auto update = [&](int begin, int end) {
    for (int i = begin; i < end; ++i) UpdateRobotComponents(m, m.robots[i], w.robots[i], w.physics, w.tick);
  };
  ForEachRobotCheap(w, update);
}

// Who hears whom, where the LEDs are, after the robots moved.
void MediaStage(World& w) {
  if (w.entities.layout_changed()) w.media.ready = false;  // changed by post_step or init
  w.entities.ClearChanged();
  UpdateMedia(w.model, w.physics, w.robots, &w.media, MediaRunner(w));
}

bool PreStepStage(World& w) {
  const bool ok = LoopCall(w, "pre_step");
  RefreshMediaIfSceneChanged(w);
  FlushLoopLog(w);
  return ok;
}

// A robot sensed and stepped this tick: alive, and its controller has not failed.
bool Runs(const RobotState& r) { return r.alive && r.controller_ok; }

// One robot's controller step(). A controller that fails stops: zero wheels from the next
// act on, never stepped again.
void ControlRobot(World& w, int i) {
  RobotState& r = w.robots[i];
  const SteppingScope stepping(i, "ControlStep");
  if (!w.controllers[i]->Step(&w.pending_errors[i])) {
    r.controller_ok = false;
    r.cmd.wheel_left = r.cmd.wheel_right = 0;
    r.cmd.wheels_new = true;
  }
}

// Robots sensed, then stepped, this many at a time: the stage clocks are read around each
// batch, 2 reads per 32 robots where sensing and stepping robot by robot read it twice a
// robot (~1.4 % of a trivial controller's robot-step). The order changes nothing: a robot's
// sense and control touch only its own state (the threads interleave them anyway). A
// batch's RobotStates (32 x 1.8 KB) stay in cache until its controllers read them.
constexpr int kTimedBatch = 32;

// Sense and control of robots [begin, end), their times added to `*times`.
void SenseAndControlRange(World& w, const SenseContext& ctx, int begin, int end, World::ChunkTimes* times) {
  Clock::time_point sense_start = Clock::now();
  for (int b = begin; b < end; b += kTimedBatch) {
    const int e = std::min(end, b + kTimedBatch);
    for (int i = b; i < e; ++i)
      if (Runs(w.robots[i])) SenseRobot(ctx, w.model.robots[i], w.robots[i]);
    const Clock::time_point control_start = Clock::now();
    for (int i = b; i < e; ++i)
      if (Runs(w.robots[i])) ControlRobot(w, i);
    const Clock::time_point control_end = Clock::now();
    times->sense += Seconds(sense_start, control_start);
    times->control += Seconds(control_start, control_end);
    sense_start = control_end;
  }
}

// Robots are independent here (each writes only its own state), so threads split them.
void SenseAndControlStage(World& w) {
  const SenseContext ctx{w.model, w.physics, w.media, w.floor, w.robots, w.tick, w.model.experiment.TickLength()};
  auto work = [&](int begin, int end) {
    World::ChunkTimes local;
    SenseAndControlRange(w, ctx, begin, end, &local);
    // Ranges are disjoint, so the range's first robot names its slot: no shared writes.
    w.chunk_times[static_cast<size_t>(begin)] = local;
  };
  // Balanced: robots cost different amounts (crowds, dead ones) and a thread may lose its
  // core for a while; measured at 2 threads, equal static chunks differed by 1.6-2.1% in
  // thread CPU time per tick (the faster thread then idles at the barrier).
  w.pool->ParallelForBalanced(static_cast<int>(w.robots.size()), work);
  for (World::ChunkTimes& t : w.chunk_times) {
    w.times.sense += t.sense;
    w.times.control += t.control;
    t = World::ChunkTimes();
  }
}

// The controllers' logs in robot order, then this tick's errors (identical ones grouped).
// False when an error ends the run (strict, or a controller called exit).
bool CollectControllerErrors(World& w) {
  bool failed = false;
  const size_t errors_before = w.controller_errors.size();
  for (size_t i = 0; i < w.controllers.size(); ++i) {
    FlushLog(w, w.controllers[i]->LogBuffer(), static_cast<int>(i));
    if (w.pending_errors[i].empty()) continue;
    w.controller_errors.push_back({w.model.robots[i].id, w.tick, w.pending_errors[i]});
    w.pending_errors[i].clear();
    if (w.options.strict || w.controllers[i]->ExitCalled()) {
      w.failure = w.controller_errors.back().message;
      failed = true;
    }
  }
  if (w.options.log_sink && w.controller_errors.size() > errors_before)
    for (const std::string& text : GroupControllerErrors(w.controller_errors, errors_before))
      w.options.log_sink('E', text, {w.tick, kLogHost});
  return !failed;
}

StepStatus PostStepStage(World& w) {
  bool ok = LoopCall(w, "post_step");
  bool finished = false;
  if (ok) {
    std::string err;
    ok = LoopExperimentFinished(w, &finished, &err);
    if (!ok) w.failure = err;
  }
  FlushLoopLog(w);
  if (!ok) return StepStatus::Failed;
  if (finished) {
    w.finished_by_loop_functions = true;
    return StepStatus::Finished;
  }
  return LengthReached(w) ? StepStatus::Finished : StepStatus::Running;
}

// Runs `stage` and adds its duration to `*total` (s).
template <class Stage>
void Timed(double* total, Stage&& stage) {
  const auto start = Clock::now();
  stage();
  *total += Seconds(start, Clock::now());
}
}  // namespace

bool LengthReached(const World& w) {
  return w.model.experiment.length_ticks > 0 && w.tick >= w.model.experiment.length_ticks;
}

StepStatus Step(World& w) {
  BeginTick(w);
  Timed(&w.times.act, [&] { ActStage(w); });
  Timed(&w.times.physics, [&] { PhysicsStage(w); });
  Timed(&w.times.media, [&] { MediaStage(w); });
  bool ok = true;
  Timed(&w.times.loop_functions, [&] { ok = PreStepStage(w); });
  if (!ok) return StepStatus::Failed;
  SenseAndControlStage(w);  // timed per batch of robots: sense and control apart
  StepStatus status = StepStatus::Failed;
  Timed(&w.times.loop_functions, [&] {
    if (CollectControllerErrors(w)) status = PostStepStage(w);
  });
  return status;
}

}  // namespace essaim
