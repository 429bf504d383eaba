// `essaim bench`: fixed scenarios, one table of robot-steps per second and where the time
// goes. Scenarios are .argos files in bench/ (found beside the sources or with --dir).
#include <sys/resource.h>

#include <chrono>
#include <cstdio>

#include "app/commands.h"
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

const Scenario kScenarios[] = {
    {"diffusion-minimal", "diffusion_1000.argos", ""},
    {"diffusion-minimal-100", "diffusion_1000.argos", "arena.distribute[2].entity.quantity=100"},
    {"rab-1000", "rab_1000.argos", ""},
    {"camera-1000", "camera_1000.argos", ""},
    {"rays-1000", "rays_1000.argos", ""},
};

double PeakRssMb() {
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}
}  // namespace

int BenchCommand(const std::vector<std::string>& args) {
  std::string dir = ESSAIM_SOURCE_DIR "/bench";
  long long ticks = 200;
  int threads = 1;
  std::string only;
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--quick") ticks = 50;
    else if (args[i] == "--dir" && i + 1 < args.size()) dir = args[++i];
    else if (args[i] == "--ticks" && i + 1 < args.size()) ticks = ParseInt(args[++i]).value_or(200);
    else if (args[i] == "--threads" && i + 1 < args.size()) threads = static_cast<int>(ParseInt(args[++i]).value_or(1));
    else if (args[i] == "--only" && i + 1 < args.size()) only = args[++i];
    else {
      std::fprintf(stderr, "essaim bench: unknown option %s\n", args[i].c_str());
      return kExitBadInput;
    }
  }
  std::printf("%-24s %7s %7s %9s %12s %10s  %5s %5s %5s %5s %5s %5s  %8s\n", "scenario", "robots", "threads",
              "ticks/s", "robot-step/s", "us/r-step", "act%", "phys%", "media%", "loop%", "sense%", "lua%", "peakMB");
  for (const Scenario& s : kScenarios) {
    if (!only.empty() && only != s.name) continue;
    LoadOptions lo;
    lo.ticks = ticks;
    lo.threads = threads;
    if (s.overrides[0]) lo.overrides.push_back(s.overrides);
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
    auto t0 = std::chrono::steady_clock::now();
    while (Step(*world) == StepStatus::Running) {
    }
    double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    double steps = static_cast<double>(world->tick) * model->robots.size();
    const StageTimes& t = world->times;
    double total = std::max(1e-12, t.Total());
    std::printf("%-24s %7zu %7d %9.1f %12.0f %10.2f  %5.1f %5.1f %5.1f %5.1f %5.1f %5.1f  %8.1f\n", s.name,
                model->robots.size(), world->threads, world->tick / wall, steps / wall, wall * 1e6 / steps,
                100 * t.act / total, 100 * t.physics / total, 100 * t.media / total, 100 * t.loop_functions / total,
                100 * t.sense / total, 100 * t.control / total, PeakRssMb());
    std::fflush(stdout);
  }
  return kExitOk;
}

}  // namespace essaim
