// `essaim bench`: fixed scenarios, one table of robot-steps per second and where the time
// goes. Scenarios are .argos files in bench/ (found beside the sources or with --dir); the
// C++ controllers they name are libraries built with essaim (bench/avoidance_cpp), found
// through ARGOS_PLUGIN_PATH, to which bench adds the folder they were built or installed in.
#include <sys/resource.h>
#include <time.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include "app/bench_scale.h"
#include "app/cli_support.h"
#include "app/commands.h"
#include "app/signals.h"
#include "core/paths.h"
#include "core/stopwatch.h"
#include "core/strings.h"
#include "lua/host/watchdog.h"
#include "model/xml_loader.h"
#include "sim/bare_floor.h"
#include "sim/step.h"

namespace essaim {

namespace {
struct Scenario {
  const char* name;
  const char* file;                    // in the bench folder
  std::vector<const char*> overrides;  // --set values
};

// The fixed scenarios. Robot counts are set with --set on the scenario's distribute.
const Scenario kScenarios[] = {
    {"diffusion-minimal", "diffusion_1000.argos", {}},
    {"diffusion-minimal-100", "diffusion_1000.argos", {"arena.distribute[2].entity.quantity=100"}},
    {"avoidance-100", "avoidance_1000.argos", {"arena.distribute[2].entity.quantity=100"}},
    {"avoidance-1000", "avoidance_1000.argos", {}},
    // The same with avoidance.lua's C++ twin (bench/avoidance_cpp): the simulator without Lua.
    {"avoidance-cpp-100", "avoidance_cpp_1000.argos", {"arena.distribute[2].entity.quantity=100"}},
    {"avoidance-cpp-1000", "avoidance_cpp_1000.argos", {}},
    {"rays-1000", "rays_1000.argos", {}},
    {"rab-1000", "rab_1000.argos", {}},
    {"camera-1000", "camera_1000.argos", {}},
    {"foraging-30", "../arenas/foraging.argos", {}},
    {"foraging-100", "../arenas/foraging.argos", {"arena.distribute.entity.quantity=100"}},
    // 300 foot-bots do not fit the 2.4 m start square: 4.4 m keeps the 100-robot density.
    {"foraging-300",
     "../arenas/foraging.argos",
     {"arena.distribute.entity.quantity=300", "arena.distribute.position.min=-2.2,-2.2,0",
      "arena.distribute.position.max=2.2,2.2,0"}},
    {"foraging30m-100", "../arenas/foraging_30m.argos", {"arena.distribute.entity.quantity=100"}},
    {"foraging30m-1000", "../arenas/foraging_30m.argos", {}},
};

// The folder holding the bench's C++ controller libraries: build/bench beside build/essaim,
// or an install's lib/essaim/bench; appended to ARGOS_PLUGIN_PATH (made if unset), where the
// scenarios' library="libbench_avoidance" is looked for first, as ARGoS looks for it.
void AddBenchPluginFolder() {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe_dir = fs::read_symlink("/proc/self/exe", ec).parent_path();
  if (ec) return;
  for (const fs::path& dir : {exe_dir / "bench", exe_dir / ".." / "lib" / "essaim" / "bench"}) {
    if (!fs::is_directory(dir, ec)) continue;
    const char* old = std::getenv("ARGOS_PLUGIN_PATH");
    const std::string path = old && *old ? std::string(old) + ":" + dir.string() : dir.string();
    setenv("ARGOS_PLUGIN_PATH", path.c_str(), 1);
    return;
  }
}

double PeakRssMb() {
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}
}  // namespace

struct BenchArgs {
  std::string dir = ESSAIM_SOURCE_DIR "/bench";
  long long ticks = 200;
  bool quick = false, strict = false;
  std::vector<int> thread_counts = {1};
  std::vector<std::string> only;
  bool floor = false;
  int repeat = 1;
};

namespace {
std::unique_ptr<Model> LoadScenario(const std::string& dir, const Scenario& s, long long ticks, int threads,
                                    bool strict) {
  LoadOptions lo;
  lo.strict = strict;
  lo.ticks = ticks;
  lo.threads = threads;
  for (const char* o : s.overrides) lo.overrides.push_back(o);
  ErrorList errors;
  auto model = LoadExperimentFile(JoinPath(dir, s.file), lo, &errors);
  if (!model) std::fputs(errors.Format().c_str(), stderr);
  return model;
}

/// One normal run: its wall and CPU time (s, CPU summed over threads) and stage times.
/// False (error printed) on failure.
bool TimeRun(const Model& model, double* wall, double* cpu, StageTimes* times) {
  Watchdog watchdog(ExitStuck);  // outlives the world
  SimOptions opt;
  opt.lua.watchdog = &watchdog;
  std::string error;
  auto world = World::Create(model, opt, &error);
  if (!world || !world->failure.empty()) {
    std::fprintf(stderr, "%s\n", world ? world->failure.c_str() : error.c_str());
    return false;
  }
  const double c0 = ProcessCpuSeconds();
  auto t0 = std::chrono::steady_clock::now();
  while (Step(*world) == StepStatus::Running) {
  }
  *wall = SecondsSince(t0);
  *cpu = ProcessCpuSeconds() - c0;
  *times = world->times;
  return true;
}

// The overhead ratio: a normal run's wall time over the controllers' bare-Lua floor on the same
// readings (sim/bare_floor.h), with each stage's share of the wall time; and the same ratio
// in CPU time, which a busy machine disturbs far less (at several threads the run's CPU
// time is summed over them). With --repeat N, each number is the minimum of N runs (the
// machine's noise only ever adds time). Two floors: "floor" on Lua's stock allocator (bare
// Lua 5.4: the ratio, wall/floor and cpu/floor), and "same" on the run's own
// small-block pool (same Lua runtime as the run: what the simulator alone adds).
const char* const kFloorDefaults[] = {"foraging-30", "foraging-100", "foraging-300", "avoidance-1000"};

int BenchFloor(const BenchArgs& a) {
  std::printf("%-16s %6s %3s %6s %10s %11s %10s %9s %9s %9s %9s %9s  %5s %5s %6s %5s %6s %5s %6s\n", "scenario",
              "robots", "thr", "ticks", "wall-us/rs", "floor-us/rs", "wall/floor", "cpu-us/rs", "floor-cpu",
              "cpu/floor", "same-cpu", "cpu/same", "act%", "phys%", "media%", "loop%", "sense%", "lua%", "other%");
  for (const Scenario& s : kScenarios) {
    const bool wanted = a.only.empty() ? std::find(std::begin(kFloorDefaults), std::end(kFloorDefaults),
                                                   std::string(s.name)) != std::end(kFloorDefaults)
                                       : std::find(a.only.begin(), a.only.end(), s.name) != a.only.end();
    if (!wanted) continue;
    auto one = LoadScenario(a.dir, s, a.ticks, 1, a.strict);
    if (!one) return kExitBadInput;
    if (std::any_of(one->controllers.begin(), one->controllers.end(), [](const ControllerDef& c) { return c.Cpp(); })) {
      std::fprintf(stderr, "%s: --floor times Lua controllers in bare Lua; this scenario's are C++ (skipped)\n",
                   s.name);
      continue;
    }
    double floor = 0, floor_cpu = 0, same_cpu = 0;
    long long steps = 0;
    for (int k = 0; k < a.repeat; ++k) {
      BareFloor f;
      std::string error;
      if (!MeasureBareFloor(*one, &f, &error)) {
        std::fprintf(stderr, "%s: %s\n", s.name, error.c_str());
        return kExitRunFailed;
      }
      floor = k == 0 ? f.step_seconds : std::min(floor, f.step_seconds);
      floor_cpu = k == 0 ? f.step_cpu_seconds : std::min(floor_cpu, f.step_cpu_seconds);
      same_cpu = k == 0 ? f.pool_step_cpu_seconds : std::min(same_cpu, f.pool_step_cpu_seconds);
      steps = f.robot_steps;
    }
    for (int threads : a.thread_counts) {
      auto model = LoadScenario(a.dir, s, a.ticks, threads, a.strict);
      if (!model) return kExitBadInput;
      double wall = 0, cpu = 0;
      StageTimes best;
      for (int k = 0; k < a.repeat; ++k) {
        double w = 0, c = 0;
        StageTimes t;
        if (!TimeRun(*model, &w, &c, &t)) return kExitBadInput;
        cpu = k == 0 ? c : std::min(cpu, c);
        if (k == 0 || w < wall) {
          wall = w;
          best = t;
        }
      }
      const double per = 1e6 / std::max<long long>(1, steps);
      const double pct = 100 / std::max(1e-12, wall);
      std::printf(
          "%-16s %6zu %3d %6lld %10.2f %11.2f %10.2f %9.2f %9.2f %9.2f %9.2f %9.2f  %5.1f %5.1f %6.1f %5.1f %6.1f "
          "%5.1f %6.1f\n",
          s.name, model->robots.size(), threads, static_cast<long long>(model->experiment.length_ticks), wall * per,
          floor * per, wall / std::max(1e-12, floor), cpu * per, floor_cpu * per, cpu / std::max(1e-12, floor_cpu),
          same_cpu * per, cpu / std::max(1e-12, same_cpu), best.act * pct, best.physics * pct, best.media * pct,
          best.loop_functions * pct, best.sense * pct, best.control * pct, (wall - best.Total()) * pct);
      std::fflush(stdout);
    }
  }
  return kExitOk;
}
}  // namespace

static int Bench(BenchArgs a) {
  if (a.floor) return BenchFloor(a);
  if (a.quick) a.ticks = 50;
  const std::string& dir = a.dir;
  long long ticks = a.ticks;
  const std::vector<int>& thread_counts = a.thread_counts;
  const std::vector<std::string>& only = a.only;
  // wall/lua: whole run time over the time inside the controllers' step() (the
  // overhead ratio). Stage shares: sense and control are summed over threads.
  std::printf("%-18s %6s %3s %8s %11s %9s %8s  %5s %5s %5s %5s %5s %5s %8s %7s\n", "scenario", "robots", "thr",
              "ticks/s", "robot-st/s", "us/r-step", "wall/lua", "act%", "phys%", "media%", "loop%", "sense%", "lua%",
              "luaKB/r", "peakMB");
  for (const Scenario& s : kScenarios) {
    if (!only.empty() && std::find(only.begin(), only.end(), s.name) == only.end()) continue;
    for (int threads : thread_counts) {
      auto model = LoadScenario(dir, s, ticks, threads, a.strict);
      if (!model) return kExitBadInput;
      Watchdog watchdog(ExitStuck);  // outlives the world
      SimOptions opt;
      opt.lua.watchdog = &watchdog;
      std::string error;
      auto world = World::Create(*model, opt, &error);
      if (!world) {
        std::fprintf(stderr, "%s\n", error.c_str());
        return kExitBadInput;
      }
      if (!world->failure.empty()) {  // an init() error
        std::fprintf(stderr, "%s\n", world->failure.c_str());
        return kExitRunFailed;
      }
      auto t0 = std::chrono::steady_clock::now();
      while (Step(*world) == StepStatus::Running) {
      }
      double wall = SecondsSince(t0);
      double steps = static_cast<double>(world->tick) * model->robots.size();
      const StageTimes& t = world->times;
      double total = std::max(1e-12, t.Total());
      size_t lua_bytes = 0;
      for (const auto& c : world->controllers) lua_bytes += c->Memory().bytes;
      std::printf("%-18s %6zu %3d %8.1f %11.0f %9.2f %8.2f  %5.1f %5.1f %5.1f %5.1f %5.1f %5.1f %8.1f %7.1f\n", s.name,
                  model->robots.size(), world->threads, world->tick / wall, steps / wall, wall * 1e6 / steps,
                  wall / std::max(1e-12, t.control), 100 * t.act / total, 100 * t.physics / total,
                  100 * t.media / total, 100 * t.loop_functions / total, 100 * t.sense / total, 100 * t.control / total,
                  lua_bytes / 1024.0 / std::max<size_t>(1, model->robots.size()), PeakRssMb());
      std::fflush(stdout);
    }
  }
  return kExitOk;
}

namespace {
CLI::App* AddScaleSubcommand(CLI::App& bench, BenchScaleArgs* s) {
  s->dir = ESSAIM_SOURCE_DIR "/bench";
  CLI::App* scale = bench.add_subcommand(
      "scale",
      "the avoidance scenario at constant density and growing robot counts: set-up and teardown seconds, "
      "us per robot-step by stage, peak KB per robot, real-time factor on 1 and N threads");
  scale->add_option("--sizes", s->sizes, "robot counts, comma-separated")
      ->type_name("N,...")
      ->delimiter(',')
      ->check(IntegerIn(1, 1000000))
      ->default_str("1000,10000,100000");
  scale->add_option("--ticks", s->ticks, "ticks per run")
      ->type_name("N")
      ->check(IntegerIn(1, 1000000000))
      ->capture_default_str();
  scale->add_option("--warmup", s->warmup, "ticks run before the timed ones, untimed")
      ->type_name("N")
      ->check(IntegerIn(0, 1000000000))
      ->capture_default_str();
  scale->add_option("--threads", s->threads, "thread count of the second real-time factor (default: the hardware's)")
      ->type_name("N")
      ->check(IntegerIn(1, 1024));
  scale->add_option("--dir", s->dir, "the folder holding avoidance_1000.argos")
      ->type_name("DIR")
      ->capture_default_str();
  scale->footer("Example:\n  essaim bench scale --sizes 1000,4000 --ticks 10 --threads 2");
  return scale;
}
}  // namespace

CommandMain AddBenchCommand(CLI::App& app) {
  auto a = std::make_shared<BenchArgs>();
  CLI::App* sub = app.add_subcommand("bench", "print robot-steps per second on fixed scenarios");
  sub->add_flag("--quick", a->quick, "50 ticks per scenario instead of --ticks");
  sub->add_flag("--strict", a->strict, "unknown attributes in a scenario file are errors (exit 2)");
  sub->add_option("--ticks", a->ticks, "ticks per scenario")
      ->type_name("N")
      ->check(IntegerIn(1, 1000000000))
      ->capture_default_str();
  sub->add_option("--threads", a->thread_counts, "thread counts to measure, comma-separated")
      ->type_name("N,...")
      ->delimiter(',')
      ->check(IntegerIn(1, 1024))
      ->default_str("1");
  std::vector<std::string> names;
  for (const Scenario& s : kScenarios) names.push_back(s.name);
  sub->add_option("--only", a->only, "scenarios to run, comma-separated (default all)")
      ->type_name("NAME,...")
      ->delimiter(',')
      ->check(CLI::IsMember(names));
  sub->add_flag("--floor", a->floor,
                "time each scenario's controllers in bare Lua on the run's own readings and print the run's "
                "wall time over that floor (default scenarios: foraging-30/100/300, avoidance-1000)");
  sub->add_option("--repeat", a->repeat, "with --floor: runs per measurement, the minimum is kept")
      ->type_name("N")
      ->check(IntegerIn(1, 100))
      ->capture_default_str();
  sub->add_option("--dir", a->dir, "the folder holding the scenario files")->type_name("DIR")->capture_default_str();
  sub->footer(
      "Example:\n  essaim bench --only avoidance-100,foraging-30 --threads 1,2\n"
      "  essaim bench --floor --only foraging-30 --ticks 100 --repeat 3\n"
      "  essaim bench scale --sizes 1000,4000 --ticks 10 --threads 2");
  auto s = std::make_shared<BenchScaleArgs>();
  CLI::App* scale = AddScaleSubcommand(*sub, s.get());
  return [a, s, scale] {
    AddBenchPluginFolder();
    if (!scale->parsed()) return Bench(*a);
    if (ReportLeftovers(*scale, "essaim bench scale")) return kExitBadInput;
    return BenchScale(*s);
  };
}

}  // namespace essaim
