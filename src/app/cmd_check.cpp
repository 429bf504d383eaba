// `essaim check`: the experiment and its scripts validated as a run would load them.
#include <stdlib.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/run_args.h"
#include "app/run_report.h"
#include "app/run_workdir.h"
#include "app/signals.h"
#include "lua/host/watchdog.h"
#include "sim/error_groups.h"
#include "sim/loop_hooks.h"
#include "sim/step.h"

namespace essaim {

namespace {
constexpr uint64_t kCheckTicks = 10;
constexpr size_t kCheckRobots = 20;

/// The robots `check` steps: the first of every distinct controller and params, then the
/// first others, up to kCheckRobots (all of them when fewer).
Model CheckSample(const Model& m) {
  Model sample = m;
  if (m.robots.size() <= kCheckRobots) return sample;
  std::vector<bool> keep(m.robots.size(), false);
  std::set<std::pair<int, AttrMap>> seen;
  size_t kept = 0;
  for (size_t i = 0; i < m.robots.size(); ++i)
    if (seen.insert({m.robots[i].controller, m.robots[i].params}).second) keep[i] = true, ++kept;
  for (size_t i = 0; i < m.robots.size() && kept < kCheckRobots; ++i)
    if (!keep[i]) keep[i] = true, ++kept;
  sample.robots.clear();
  for (size_t i = 0; i < m.robots.size(); ++i)
    if (keep[i]) sample.robots.push_back(m.robots[i]);
  return sample;
}

/// Steps the sample as `run` would, quietly; every problem goes into `problems` (one per line).
void CheckSteps(World& world, uint64_t ticks, std::string* problems) {
  size_t reported = 0;
  auto report = [&] {
    for (const std::string& e : GroupControllerErrors(world.controller_errors, reported)) *problems += e + "\n";
    reported = world.controller_errors.size();
  };
  report();  // init()
  StepStatus status = world.failure.empty() ? StepStatus::Running : StepStatus::Failed;
  while (status == StepStatus::Running && world.tick < ticks) {
    status = Step(world);
    report();
  }
  if (!world.failure.empty()) *problems += world.failure + "\n";
  if (status != StepStatus::Failed) *problems += FormatUnreadParams(FindUnreadParams(world), true);
}

/// A warning when nothing ends the run: no length (nor --ticks), and no loop functions that
/// can (a misspelt length="..." did this silently). "" when something ends it.
std::string NoEndWarning(const std::string& file, World& world) {
  if (world.model.experiment.length_ticks != 0) return "";
  const std::string head = file + ": warning: the run has no end: no length in <experiment> and no --ticks";
  switch (LoopFunctionsEnd(world)) {
    case LoopEnd::kFunction:
      return "";
    case LoopEnd::kUnknown:
      return head + ", so it runs until Ctrl-C unless the loop functions end it (IsExperimentFinished)\n";
    case LoopEnd::kNoFunction:
      return head + ", and the loop functions define no is_experiment_finished(): it runs until Ctrl-C\n";
    case LoopEnd::kNone:
      break;
  }
  return head + ", and no loop functions: it runs until Ctrl-C\n";
}

/// A temporary folder removed with everything in it when the check ends: check's scripts
/// run there, as a run's do in <out>/files, and write nowhere the user keeps results.
class TemporaryWorkdir {
 public:
  bool Enter(const std::string& argos_file, std::string* error) {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/essaim-check-XXXXXX";
    if (!::mkdtemp(pattern.data())) {
      *error = "cannot make a temporary working folder " + pattern;
      return false;
    }
    folder_ = pattern;
    std::string warning;
    return workdir_.Enter(folder_, argos_file, {}, &warning, error);
  }
  ~TemporaryWorkdir() {
    workdir_.Leave();
    std::error_code ec;
    if (!folder_.empty()) std::filesystem::remove_all(folder_, ec);
  }

 private:
  std::string folder_;
  RunWorkdir workdir_;
};
}  // namespace

static int Check(RunArgs& r) {
  std::string error;
  if (!ApplyOptions(&r, &error)) {
    std::fprintf(stderr, "essaim check: %s\n", error.c_str());
    return kExitBadInput;
  }
  r.file = NamedFromBelow(r.file);
  auto model = LoadOrReport(r);
  if (!model) return kExitBadInput;
  AnchorPathsAbove(model.get());
  // The scripts too: load every controller and the loop functions, run init() and a few
  // ticks on a sample of the robots, as a run would, with no output.
  const Model sample = CheckSample(*model);
  TemporaryWorkdir workdir;  // declared before the world, so left after it
  if (!workdir.Enter(model->file, &error)) {
    std::fprintf(stderr, "essaim check: %s\n", error.c_str());
    return kExitRunFailed;
  }
  Watchdog watchdog(ExitStuck);
  SimOptions opt;
  opt.output_dir = "";
  opt.lua = WatchdogOptions(*model, r);
  opt.lua.watchdog = &watchdog;
  auto world = World::Create(sample, opt, &error);
  if (!world) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return kExitBadInput;
  }
  uint64_t length = model->experiment.length_ticks;
  uint64_t ticks = r.ticks ? length : (length == 0 ? kCheckTicks : std::min(length, kCheckTicks));
  std::string problems;
  CheckSteps(*world, ticks, &problems);
  if (!problems.empty()) {
    std::fputs(problems.c_str(), stderr);
    std::fprintf(stderr, "essaim check: %s: problems found in init() and %llu ticks of %zu robots\n", r.file.c_str(),
                 static_cast<unsigned long long>(world->tick), sample.robots.size());
    return kExitBadInput;
  }
  if (!r.quiet) std::fputs(NoEndWarning(r.file, *world).c_str(), stderr);
  std::printf("%s: ok (%zu robots, %zu obstacles, %s; init() and %llu ticks run on %zu robots)\n", r.file.c_str(),
              model->robots.size(), model->obstacles.size(),
              length ? (std::to_string(length) + " ticks").c_str() : "no length",
              static_cast<unsigned long long>(world->tick), sample.robots.size());
  return kExitOk;
}

CommandMain AddCheckCommand(CLI::App& app) {
  auto r = std::make_shared<RunArgs>();
  CLI::App* sub = app.add_subcommand("check", "validate an experiment and its scripts, list every error");
  AddExperimentOptions(sub, r.get());
  sub->add_flag("-q,--quiet", r->quiet, "errors only, no warnings");
  sub->add_flag("--strict", r->strict, "unknown attributes in the file are errors (exit 2), not warnings");
  sub->footer("Example:\n  essaim check arenas/foraging.argos --set arena.distribute.entity.quantity=60");
  return [r] { return Check(*r); };
}

}  // namespace essaim
