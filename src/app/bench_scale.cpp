// `essaim bench scale`: the avoidance scenario grown at constant density (1 000 foot-bots per
// 32 m × 32 m, 100 boxes and 100 cylinders per 1 000 robots), so that what grows faster than
// the robot count shows: set-up (wall and CPU) and teardown seconds, µs per robot-step by stage (after warm-up
// ticks, so that the Lua states' first collections do not weigh on the small sizes), peak
// memory per robot, real-time factor on 1 and N threads.
#include "app/bench_scale.h"

#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <thread>

#include "app/commands.h"
#include "app/signals.h"
#include "core/paths.h"
#include "core/stopwatch.h"
#include "lua/host/watchdog.h"
#include "model/xml_loader.h"
#include "sim/step.h"

namespace essaim {

namespace {
using Clock = std::chrono::steady_clock;

std::string Num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

/// --set values that scale bench/avoidance_1000.argos (1 000 robots in 32 m × 32 m, walls
/// at ±16 m, everything placed in ±15 m) to `robots` at the same density.
std::vector<std::string> ScaleOverrides(long long robots) {
  const double s = std::sqrt(robots / 1000.0);
  const std::string side = Num(32 * s), wall = Num(16 * s), half = Num(15 * s);
  const std::string obstacles = std::to_string(std::max(1LL, robots / 10));
  std::vector<std::string> o = {
      "arena.size=" + side + "," + side + ",1",           "arena.wall_north.size=" + side + ",0.1,0.5",
      "arena.wall_south.size=" + side + ",0.1,0.5",       "arena.wall_east.size=0.1," + side + ",0.5",
      "arena.wall_west.size=0.1," + side + ",0.5",        "arena.wall_north.body.position=0," + wall + ",0",
      "arena.wall_south.body.position=0,-" + wall + ",0", "arena.wall_east.body.position=" + wall + ",0,0",
      "arena.wall_west.body.position=-" + wall + ",0,0",
  };
  for (int d = 0; d < 3; ++d) {
    const std::string at = "arena.distribute[" + std::to_string(d) + "].";
    o.push_back(at + "position.min=-" + half + ",-" + half + ",0");
    o.push_back(at + "position.max=" + half + "," + half + ",0");
    o.push_back(at + "entity.quantity=" + (d == 2 ? std::to_string(robots) : obstacles));
  }
  return o;
}

/// Peak resident set: the kernel's high-water mark (VmHWM), which ResetPeakRss sets back to
/// the current resident set. KB.
long long PeakRssKb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::atoll(line.c_str() + 6);
  return -1;
}

/// Gives freed heap back to the system and restarts the peak there, so that one size's peak
/// does not carry the last one's. False when the kernel refuses (then peaks only grow).
bool ResetPeakRss() {
  malloc_trim(0);
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  clear.flush();
  return static_cast<bool>(clear);
}

StageTimes Minus(const StageTimes& a, const StageTimes& b) {
  StageTimes d;
  d.act = a.act - b.act;
  d.physics = a.physics - b.physics;
  d.media = a.media - b.media;
  d.loop_functions = a.loop_functions - b.loop_functions;
  d.sense = a.sense - b.sense;
  d.control = a.control - b.control;
  return d;
}

struct ScaleRun {
  double setup = 0, wall = 0, simulated = 0;  // s
  double setup_cpu = 0;                       // CPU s of the set-up (all threads)
  double teardown = 0;                        // s: the World (Lua states included) and the Model freed
  StageTimes times;
  long long peak_kb = 0;
  size_t robots = 0;
  uint64_t ticks = 0;
};

/// Loads and builds the scaled scenario on `threads` threads (the set-up), runs the warm-up
/// ticks untimed, then times the rest to the end. False (error printed) on failure.
bool RunScaled(const BenchScaleArgs& a, long long robots, int threads, ScaleRun* out) {
  const auto t0 = Clock::now();
  const double c0 = ProcessCpuSeconds();
  LoadOptions lo;
  lo.ticks = a.warmup + a.ticks;
  lo.threads = threads;
  lo.overrides = ScaleOverrides(robots);
  ErrorList errors;
  auto model = LoadExperimentFile(JoinPath(a.dir, "avoidance_1000.argos"), lo, &errors);
  if (!model) {
    std::fputs(errors.Format().c_str(), stderr);
    return false;
  }
  Watchdog watchdog(ExitStuck);  // outlives the world
  SimOptions opt;
  opt.lua.watchdog = &watchdog;
  std::string error;
  auto world = World::Create(*model, opt, &error);
  if (!world || !world->failure.empty()) {
    std::fprintf(stderr, "%s\n", world ? world->failure.c_str() : error.c_str());
    return false;
  }
  out->setup = SecondsSince(t0);
  out->setup_cpu = ProcessCpuSeconds() - c0;
  StepStatus status = StepStatus::Running;
  while (world->tick < static_cast<uint64_t>(a.warmup) && status == StepStatus::Running) status = Step(*world);
  const StageTimes warm = world->times;
  const uint64_t warm_ticks = world->tick;
  const auto t1 = Clock::now();
  while (status == StepStatus::Running) status = Step(*world);
  out->wall = SecondsSince(t1);
  out->times = Minus(world->times, warm);
  out->robots = model->robots.size();
  out->ticks = world->tick - warm_ticks;
  out->simulated = out->ticks * model->experiment.TickLength();
  out->peak_kb = PeakRssKb();
  const auto t2 = Clock::now();
  world.reset();
  model.reset();
  out->teardown = SecondsSince(t2);
  return true;
}

void PrintHeader(int threads) {
  std::printf("%8s %8s %9s %7s %9s %8s %7s %7s %7s %7s %9s %8s", "robots", "setup-s", "setup-cpu", "down-s",
              "us/r-step", "vs-first", "phys", "sense", "ctrl", "other", "peakKB/r", "rtf-1");
  if (threads > 1)
    std::printf(" %8s %8s", ("rtf-" + std::to_string(threads)).c_str(), ("setup-" + std::to_string(threads)).c_str());
  std::printf("\n");
}

/// µs per robot-step on one thread.
double PerRobotStep(const ScaleRun& run) {
  return run.wall * 1e6 / std::max(1.0, static_cast<double>(run.robots) * run.ticks);
}

/// `first_cost`: the first size's µs per robot-step, for the vs-first column.
void PrintRow(const ScaleRun& one, const ScaleRun* many, double first_cost) {
  const double per = 1e6 / std::max(1.0, static_cast<double>(one.robots) * one.ticks);
  const StageTimes& t = one.times;
  const double other = one.wall - t.physics - t.sense - t.control;
  std::printf("%8zu %8.2f %9.2f %7.2f %9.2f %8.2f %7.2f %7.2f %7.2f %7.2f %9.1f %8.2f", one.robots, one.setup,
              one.setup_cpu, one.teardown, PerRobotStep(one), PerRobotStep(one) / first_cost, t.physics * per,
              t.sense * per, t.control * per, other * per,
              static_cast<double>(one.peak_kb) / std::max<size_t>(1, one.robots), one.simulated / one.wall);
  if (many) std::printf(" %8.2f %8.2f", many->simulated / many->wall, many->setup);
  std::printf("\n");
  std::fflush(stdout);
}
}  // namespace

int BenchScale(const BenchScaleArgs& a) {
  const int threads = a.threads > 0 ? a.threads : std::max(1u, std::thread::hardware_concurrency());
  PrintHeader(threads);
  double first_cost = 0;
  for (long long robots : a.sizes) {
    if (!ResetPeakRss()) std::fputs("bench scale: cannot reset the peak resident set; peaks only grow\n", stderr);
    ScaleRun one, many;
    if (!RunScaled(a, robots, 1, &one)) return kExitBadInput;
    if (threads > 1 && !RunScaled(a, robots, threads, &many)) return kExitBadInput;
    if (first_cost == 0) first_cost = PerRobotStep(one);
    PrintRow(one, threads > 1 ? &many : nullptr, first_cost);
  }
  return kExitOk;
}

}  // namespace essaim
