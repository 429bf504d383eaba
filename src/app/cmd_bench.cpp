// `essaim bench`: fixed scenarios, one table of robot-steps per second and where the time
// goes. Scenarios are .argos files in bench/ (found beside the sources or with --dir).
#include <sys/resource.h>

#include <algorithm>
#include <CLI/CLI.hpp>
#include <chrono>
#include <memory>
#include <cstdio>

#include "app/cli_support.h"
#include "app/commands.h"
#include "core/paths.h"
#include "core/strings.h"
#include "model/xml_loader.h"
#include "sim/step.h"

namespace essaim {

namespace {
struct Scenario {
  const char* name;
  const char* file;       // in the bench folder
  const char* overrides;  // one --set, or ""
};

// Issue 7's fixed scenarios. Robot counts are set with --set on the scenario's distribute.
const Scenario kScenarios[] = {
    {"diffusion-minimal", "diffusion_1000.argos", ""},
    {"diffusion-minimal-100", "diffusion_1000.argos", "arena.distribute[2].entity.quantity=100"},
    {"avoidance-100", "avoidance_1000.argos", "arena.distribute[2].entity.quantity=100"},
    {"avoidance-1000", "avoidance_1000.argos", ""},
    {"rays-1000", "rays_1000.argos", ""},
    {"rab-1000", "rab_1000.argos", ""},
    {"camera-1000", "camera_1000.argos", ""},
    {"foraging-30", "../arenas/foraging.argos", ""},
    {"foraging-100", "../arenas/foraging.argos", "arena.distribute.entity.quantity=100"},
    {"foraging30m-100", "../arenas/foraging_30m.argos", "arena.distribute.entity.quantity=100"},
    {"foraging30m-1000", "../arenas/foraging_30m.argos", ""},
};

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
};

static int Bench(BenchArgs a) {
  if (a.quick) a.ticks = 50;
  const std::string& dir = a.dir;
  long long ticks = a.ticks;
  const std::vector<int>& thread_counts = a.thread_counts;
  const std::vector<std::string>& only = a.only;
  // wall/lua: whole run time over the time inside the controllers' step() (issue 7's
  // overhead ratio). Stage shares: sense and control are summed over threads.
  std::printf("%-18s %6s %3s %8s %11s %9s %8s  %5s %5s %5s %5s %5s %5s %8s %7s\n", "scenario", "robots", "thr",
              "ticks/s", "robot-st/s", "us/r-step", "wall/lua", "act%", "phys%", "media%", "loop%", "sense%", "lua%",
              "luaKB/r", "peakMB");
  for (const Scenario& s : kScenarios) {
    if (!only.empty() && std::find(only.begin(), only.end(), s.name) == only.end()) continue;
    for (int threads : thread_counts) {
      LoadOptions lo;
      lo.ticks = ticks;
      lo.threads = threads;
      if (s.overrides[0]) lo.overrides.push_back(s.overrides);
      lo.strict = a.strict;
      ErrorList errors;
      auto model = LoadExperimentFile(JoinPath(dir, s.file), lo, &errors);
      if (!model) {
        std::fputs(errors.Format().c_str(), stderr);
        return kExitBadInput;
      }
      SimOptions opt;
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
      double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      double steps = static_cast<double>(world->tick) * model->robots.size();
      const StageTimes& t = world->times;
      double total = std::max(1e-12, t.Total());
      size_t lua_bytes = 0;
      for (const auto& c : world->controllers) lua_bytes += c->Memory().bytes;
      std::printf("%-18s %6zu %3d %8.1f %11.0f %9.2f %8.2f  %5.1f %5.1f %5.1f %5.1f %5.1f %5.1f %8.1f %7.1f\n", s.name,
                  model->robots.size(), world->threads, world->tick / wall, steps / wall, wall * 1e6 / steps,
                  wall / std::max(1e-12, t.control), 100 * t.act / total, 100 * t.physics / total,
                  100 * t.media / total, 100 * t.loop_functions / total, 100 * t.sense / total,
                  100 * t.control / total, lua_bytes / 1024.0 / std::max<size_t>(1, model->robots.size()),
                  PeakRssMb());
      std::fflush(stdout);
    }
  }
  return kExitOk;
}

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
  sub->add_option("--dir", a->dir, "the folder holding the scenario files")->type_name("DIR")->capture_default_str();
  sub->footer("Example:\n  essaim bench --only avoidance-1000,rab-1000 --threads 1,2");
  return [a] { return Bench(*a); };
}

}  // namespace essaim
