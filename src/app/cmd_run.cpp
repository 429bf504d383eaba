// `essaim run` and `essaim check`.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <vector>

#include "app/cli_support.h"
#include "app/commands.h"
#include "app/log_printer.h"
#include "app/run_report.h"
#include "app/set_file.h"
#include "core/paths.h"
#include "core/strings.h"
#include "lua/lua_guard.h"
#include "model/xml_loader.h"
#include "output/atomic_file.h"
#include "output/out_folder.h"
#include "output/memory_log.h"
#include "output/recording.h"
#include "output/summary.h"
#include "serve/experiment_inputs.h"
#include "serve/file_watcher.h"
#include "sim/error_groups.h"
#include "sim/step.h"

namespace essaim {

namespace {
// SIGINT and SIGTERM (what SLURM and Dask send) end the run the same way: status
// "interrupted", whole outputs, exit 128 + signal. A controller stuck in Lua is stopped
// through the watchdog's hook.
std::atomic<int> g_interrupted{0};
void OnSignal(int sig) {
  g_interrupted = sig;
  RequestLuaInterrupt();
}

constexpr long long kMaxTicks = 1000000000000LL;  // ~3 years at 10 ticks/s
constexpr long long kMaxThreads = 1024;

struct RunArgs {
  std::string file;
  std::string out;
  std::string set_file;
  std::optional<long long> ticks, seed, threads;
  std::string record;  // --record's value: "" or every=N
  LoadOptions load;
  bool quiet = false, strict = false, sandbox = false;
  bool watch = false;       // --watch: run again whenever an input file changes
  bool log_prefix = false;  // --log-prefix: "[t=120 fb7] " before each log line
  std::string log_dir;      // --log-dir: one file per robot
  uint32_t record_every = 0;  // --record: a frame every N ticks (0: no recording)
  long long memory_log_every = 0;  // --memory-log N: memory.csv every N ticks (0: none)
  long long lua_budget = -1, lua_memory_mib = -1;  // -1: the experiment's or the default
  double lua_seconds = -1;                          // wall clock per Lua call; -1: default
};

// The run in progress, for the watchdog's last resort (a call stuck inside a C function).
struct RunInProgress {
  std::string out;
  const RunArgs* args = nullptr;
  const Model* model = nullptr;
  const World* world = nullptr;       // null while init() runs
  RecordingWriter* recorder = nullptr;
  RunInfo info;
};
RunInProgress g_run;
// Held from before the first write into --out until the process ends.
OutFolderLock g_out_lock;

void OnLuaStuck(const std::string& message) {
  // Called from the monitor thread while robots may still be stepped: a best-effort summary.
  std::string error;
  if (!g_run.world) {  // stuck in the loading or init() of a script
    if (g_run.args)
      WriteFailureSummary(g_run.out, ESSAIM_VERSION, g_run.args->file, g_run.args->load.overrides, g_run.model,
                          /*inputs=*/nullptr, message, &error);
    return;
  }
  RunInfo info = g_run.info;
  info.status = "failed";
  info.finished_by = "error";
  info.outputs = {"summary.json"};
  // The frames written so far end at a whole tick: sealed as they are, never left as a
  // temporary file.
  if (g_run.recorder && g_run.recorder->IsOpen() && g_run.recorder->Seal(&error)) info.outputs.push_back(kRecordingFile);
  info.failure = message;
  WriteFileAtomic(JoinPath(g_run.out, "summary.json"), SummaryJsonText(*g_run.world, info), &error);
}

// From before the scripts load to after the world goes: signals end the run as
// interrupted, and the watchdog's last resort knows where to write.
struct WatchRun {
  WatchRun(const std::string& out, const RunArgs& r, const Model& model) {
    g_run.out = out;
    g_run.args = &r;
    g_run.model = &model;
    g_run.info.version = ESSAIM_VERSION;
    SetLuaStuckHandler(OnLuaStuck);
    std::signal(SIGINT, OnSignal);
    std::signal(SIGTERM, OnSignal);
  }
  ~WatchRun() {
    SetLuaStuckHandler(nullptr);
    g_run = RunInProgress();
  }
};

// The options run and check share: the file and what overrides its XML.
void AddExperimentOptions(CLI::App* sub, RunArgs* r) {
  sub->add_option("FILE.argos", r->file, "the ARGoS experiment file")->required();
  sub->add_option("--ticks", r->ticks, "run exactly N ticks, N >= 1 (overrides the experiment length)")
      ->type_name("N")
      ->check(IntegerIn(1, kMaxTicks, "0 would mean no limit; for that set framework.experiment.length=0"));
  sub->add_option("--seed", r->seed, "random seed, >= 0 (overrides random_seed)")
      ->type_name("S")
      ->check(IntegerIn(0, std::numeric_limits<long long>::max()));
  sub->add_option("--threads", r->threads, "threads for sense + control, 1 to 1024 (overrides <system threads>)")
      ->type_name("N")
      ->check(IntegerIn(1, kMaxThreads, "1 runs everything on the main thread"));
  sub->add_option("--set", r->load.overrides, "override an XML attribute (repeatable), e.g. controllers.ctrl.params.speed=20")
      ->type_name("PATH=VALUE")
      ->allow_extra_args(false);
  sub->add_option("--set-file", r->set_file,
                  "a JSON object {\"PATH\": value, ...} of overrides, applied before the --set ones")
      ->type_name("FILE.json");
}

// --set-file's entries first, so a --set on the command line wins over the file.
bool ApplyOptions(RunArgs* r, std::string* error) {
  if (r->ticks) r->load.ticks = static_cast<uint64_t>(*r->ticks);
  if (r->seed) r->load.seed = static_cast<uint64_t>(*r->seed);
  if (r->threads) r->load.threads = static_cast<int>(*r->threads);
  r->load.strict = r->strict;
  if (r->set_file.empty()) return true;
  std::vector<std::string> from_file;
  if (!ReadOverridesFile(r->set_file, &from_file, error)) return false;
  r->load.overrides.insert(r->load.overrides.begin(), from_file.begin(), from_file.end());
  return true;
}

// --record's value: every=N, N from 1 to 1000000. A bare word (a file name after --record)
// is refused rather than taken as the value.
CLI::Validator RecordEvery() {
  return CLI::Validator(
      [](std::string& v) -> std::string {
        auto n = v.rfind("every=", 0) == 0 ? ParseInt(v.substr(6)) : std::nullopt;
        if (v.empty() || (n && *n >= 1 && *n <= 1000000)) return "";
        return "'" + v + "' must be every=N with N from 1 to 1000000 (or give --record alone)";
      },
      "");
}

std::unique_ptr<Model> LoadOrReport(const RunArgs& r, std::string* message = nullptr) {
  ErrorList errors, warnings;
  auto model = LoadExperimentFile(r.file, r.load, &errors, &warnings);
  if (!r.quiet)
    for (const InputError& w : warnings.Items()) {
      ErrorList one;
      one.Add(w.file, w.line, w.element, "warning: " + w.message);
      std::fputs(one.Format().c_str(), stderr);
    }
  if (!model) std::fputs(errors.Format().c_str(), stderr);
  if (!model && message) {
    *message = errors.Format();
    while (!message->empty() && message->back() == '\n') message->pop_back();
  }
  return model;
}

/// The watchdog's limits: the CLI's, else the experiment's, else the defaults (stricter
/// under --sandbox). docs/sandbox.md.
LuaOptions WatchdogOptions(const Model& m, const RunArgs& r) {
  LuaOptions o;
  o.sandbox = r.sandbox;
  if (r.sandbox) {
    o.memory_limit = size_t{64} << 20;
    o.instruction_limit = 100000000;
  }
  long long budget = r.lua_budget >= 0 ? r.lua_budget : m.experiment.lua_budget;
  long long mib = r.lua_memory_mib >= 0 ? r.lua_memory_mib : m.experiment.lua_memory_mib;
  if (budget >= 0) o.instruction_limit = budget;
  if (mib >= 0) o.memory_limit = static_cast<size_t>(mib) << 20;
  if (r.lua_seconds >= 0) o.wall_seconds = r.lua_seconds;
  return o;
}

std::string DefaultOutDir(const Model& m) {
  std::filesystem::path name = std::filesystem::path(m.file).filename();
  if (name.extension() == ".argos") name = name.stem();
  return "runs/" + name.string() + "-" + std::to_string(m.experiment.seed);
}
}  // namespace

/// The folder will hold this run's outputs only: an earlier run's go into previous/, and
/// stderr says which.
static bool SetAsideEarlierOutputsAndSay(const std::string& out, std::string* error) {
  std::vector<std::string> moved;
  if (!SetAsideEarlierOutputs(out, &moved, error)) return false;
  if (!moved.empty()) {
    std::string names;
    for (const std::string& name : moved) names += (names.empty() ? "" : ", ") + name;
    std::fprintf(stderr, "essaim run: %s held an earlier run's outputs; moved them into %s: %s\n", out.c_str(),
                 JoinPath(out, kPreviousRunFolder).c_str(), names.c_str());
  }
  return true;
}

/// A run that fails before its world exists still leaves summary.json (status "failed",
/// the message) where the output goes, when that is known and usable, with an earlier
/// run's outputs set aside so the summary is not read beside them; returns `code`.
static int FailedBeforeRun(const RunArgs& r, const std::string& out, const Model* model, const std::string& message,
                           int code, const InputFiles* inputs = nullptr) {
  std::string error;
  if (out.empty()) return code;
  if (!PrepareOutFolder(out, &error) || (!g_out_lock.Held() && !g_out_lock.Acquire(out, &error)) ||
      !SetAsideEarlierOutputsAndSay(out, &error) ||
      !WriteFailureSummary(out, ESSAIM_VERSION, r.file, r.load.overrides, model, inputs, message, &error))
    std::fprintf(stderr, "essaim run: %s\n", error.c_str());
  return code;
}

/// A run whose world exists but that cannot go on (an output that cannot be opened):
/// summary.json with status "failed" and the message, exit 1.
static int FailedRun(World& world, const std::string& out, const std::string& message) {
  std::fprintf(stderr, "essaim run: %s\n", message.c_str());
  RunInfo info;
  info.version = ESSAIM_VERSION;
  info.status = "failed";
  info.finished_by = "error";
  world.failure = message;
  std::string error;
  if (!WriteRunOutputs(out, world, info, nullptr, &error)) std::fprintf(stderr, "essaim run: %s\n", error.c_str());
  return kExitRunFailed;
}

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
}  // namespace

static int Check(RunArgs& r) {
  std::string error;
  if (!ApplyOptions(&r, &error)) {
    std::fprintf(stderr, "essaim check: %s\n", error.c_str());
    return kExitBadInput;
  }
  auto model = LoadOrReport(r);
  if (!model) return kExitBadInput;
  // The scripts too: load every controller and the loop functions, run init() and a few
  // ticks on a sample of the robots, as a run would, with no output.
  const Model sample = CheckSample(*model);
  SimOptions opt;
  opt.output_dir = "";
  opt.lua = WatchdogOptions(*model, r);
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
  std::printf("%s: ok (%zu robots, %zu obstacles, %llu ticks; init() and %llu ticks run on %zu robots)\n",
              r.file.c_str(), model->robots.size(), model->obstacles.size(),
              static_cast<unsigned long long>(model->experiment.length_ticks),
              static_cast<unsigned long long>(world->tick), sample.robots.size());
  return kExitOk;
}

/// One run. `inputs` receives the files it read (to watch) as soon as they are known.
static int Run(RunArgs& r, std::vector<std::string>* inputs) {
  std::string error;
  if (!ApplyOptions(&r, &error)) {
    std::fprintf(stderr, "essaim run: %s\n", error.c_str());
    return FailedBeforeRun(r, r.out, nullptr, error, kExitBadInput);
  }
  auto model = LoadOrReport(r, &error);
  if (!model) return FailedBeforeRun(r, r.out, nullptr, error, kExitBadInput);
  *inputs = ExperimentInputs(*model, nullptr);
  std::string out = r.out.empty() ? DefaultOutDir(*model) : r.out;
  // Before any script runs: a wrong --out, or one another run is writing, is bad input.
  if (!PrepareOutFolder(out, &error) || !g_out_lock.Acquire(out, &error)) {
    std::fprintf(stderr, "essaim run: %s\n", error.c_str());
    return kExitBadInput;
  }

  SimOptions opt;
  opt.output_dir = out;
  opt.strict = r.strict;
  opt.lua = WatchdogOptions(*model, r);
  opt.inputs = std::make_shared<InputFiles>();  // kept when a script fails to load
  auto logs = std::make_shared<LogPrinter>(*model, r.log_prefix, r.log_dir);
  if (!logs->Prepare(&error)) {
    std::fprintf(stderr, "essaim run: --log-dir: %s\n", error.c_str());
    return kExitBadInput;
  }
  opt.log_sink = [logs](char stream, const std::string& line, const LogOrigin& from) { logs->Print(stream, line, from); };
  // Signals and the watchdog's last resort are handled from before init(): a controller
  // stuck there still ends the run with its outputs.
  WatchRun watch(out, r, *model);  // declared before the world, so it goes after it
  auto t0 = std::chrono::steady_clock::now();
  auto world = World::Create(*model, opt, &error);
  if (!world) {  // a script that does not load, or one a signal stopped while it loaded
    std::fprintf(stderr, "%s\n", error.c_str());
    return FailedBeforeRun(r, out, model.get(), error, g_interrupted ? 128 + g_interrupted.load() : kExitBadInput,
                           opt.inputs.get());
  }
  *inputs = ExperimentInputs(*model, world.get());
  if (!SetAsideEarlierOutputsAndSay(out, &error)) {
    std::fprintf(stderr, "essaim run: %s\n", error.c_str());
    return kExitRunFailed;
  }
  RunInfo info;
  info.version = ESSAIM_VERSION;
  // A recording that cannot be written (a full disk) does not stop the run: the other
  // outputs are still written, and the run ends with exit 1.
  RecordingWriter recorder;
  if (r.record_every > 0 && !recorder.Open(JoinPath(out, kRecordingFile), *world, r.record_every, &error))
    std::fprintf(stderr, "essaim run: %s; the run goes on without a recording\n", error.c_str());
  MemoryLog memory_log;
  if (r.memory_log_every > 0 && !memory_log.Open(JoinPath(out, kMemoryLogFile), r.memory_log_every, &error))
    return FailedRun(*world, out, error);
  g_run.world = world.get();
  g_run.recorder = &recorder;
  struct ForgetWorld {  // before the world and the recorder go
    ~ForgetWorld() {
      g_run.world = nullptr;
      g_run.recorder = nullptr;
    }
  } forget_world;
  Progress progress(!r.quiet && isatty(STDERR_FILENO), model->experiment.length_ticks, model->robots.size());
  logs->SetProgress(&progress);
  StepStatus status = StepStatus::Running;
  if (LengthReached(*world)) status = StepStatus::Finished;
  if (!world->failure.empty()) status = StepStatus::Failed;  // init() failed
  while (status == StepStatus::Running) {
    if (g_interrupted) {
      info.status = "interrupted";
      info.finished_by = "interrupted";
      break;
    }
    status = Step(*world);
    if (recorder.IsOpen()) {
      recorder.Record(*world);
      if (!recorder.IsOpen()) {
        progress.Finish();
        std::fprintf(stderr, "essaim run: %s at tick %llu; the run goes on without a recording\n",
                     recorder.Failure().c_str(), static_cast<unsigned long long>(world->tick));
      }
    }
    memory_log.Sample(*world);
    progress.Update(world->tick);
  }
  progress.Finish();
  logs->SetProgress(nullptr);
  if (g_interrupted && status == StepStatus::Failed) {
    // A loop-function hook stopped by the signal: the run was interrupted, not broken.
    info.status = "interrupted";
    info.finished_by = "interrupted";
    status = StepStatus::Running;
    world->failure.clear();
  }
  Value metrics;
  bool has_metrics = false;
  EndRun(*world, status, &info, &metrics, &has_metrics);
  if (!logs->Flush(&error)) std::fprintf(stderr, "essaim run: --log-dir: %s\n", error.c_str());
  info.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // The recording ends with the run, however it ended (interrupted and failed runs too).
  if (r.record_every > 0) {
    if (recorder.Finish(*world, &error)) info.outputs.push_back(kRecordingFile);
    else info.output_errors.push_back(error);
  }
  if (memory_log.IsOpen()) {
    if (memory_log.Close(&error)) info.outputs.push_back(kMemoryLogFile);
    else info.output_errors.push_back(error);
  }
  std::vector<std::string> unwritten = info.output_errors;
  bool all_written = WriteRunOutputs(out, *world, info, has_metrics ? &metrics : nullptr, &error);
  if (!all_written) unwritten.push_back(error);  // metrics, time series or summary
  if (!world->failure.empty()) std::fprintf(stderr, "essaim run: %s\n", world->failure.c_str());
  if (!r.quiet || r.strict) std::fputs(FormatUnreadParams(world->unread_params, r.strict).c_str(), stderr);
  if (!unwritten.empty()) {
    for (const std::string& e : unwritten) std::fprintf(stderr, "essaim run: %s\n", e.c_str());
    std::fprintf(stderr, "essaim run: the outputs in %s are incomplete%s\n", out.c_str(),
                 FileExists(JoinPath(out, "summary.json")) ? "; summary.json lists those written" : "");
    if (info.status != "interrupted") return kExitRunFailed;
  }
  if (!r.quiet) {
    double steps = static_cast<double>(world->tick) * model->robots.size();
    std::printf("essaim: %llu ticks, %zu robots, %.2f s, %.0f robot-steps/s; %zu controller error(s); output in %s\n",
                static_cast<unsigned long long>(world->tick), model->robots.size(), info.wall_seconds,
                info.wall_seconds > 0 ? steps / info.wall_seconds : 0.0, world->controller_errors.size(), out.c_str());
  }
  if (info.status == "interrupted") return 128 + (g_interrupted ? g_interrupted.load() : SIGINT);
  if (status == StepStatus::Failed || info.status == "failed") return kExitRunFailed;
  if (r.strict && (!world->controller_errors.empty() || !world->unread_params.empty())) return kExitRunFailed;
  return kExitOk;
}

/// --watch: run, then wait for a change to a file the run read, and run again, until
/// Ctrl-C (exit 0; a run it interrupts still leaves whole outputs).
static int WatchAndRun(const RunArgs& args) {
  FileWatcher watcher;
  if (!watcher.Ok()) {
    std::fprintf(stderr, "essaim run: --watch: %s\n", watcher.Error().c_str());
    return kExitBadInput;
  }
  std::signal(SIGINT, OnSignal);
  std::signal(SIGTERM, OnSignal);
  // Every file any run read: a run that failed on a broken module no longer lists it, and
  // its fix must still be seen.
  std::set<std::string> watched = {args.file};
  while (true) {
    RunArgs r = args;  // each run applies --set-file and the options afresh
    std::vector<std::string> inputs;
    Run(r, &inputs);
    std::fflush(stdout);
    if (g_interrupted) return kExitOk;
    watched.insert(inputs.begin(), inputs.end());
    watcher.Watch({watched.begin(), watched.end()});
    if (!watcher.Error().empty()) std::fprintf(stderr, "essaim run: --watch: %s\n", watcher.Error().c_str());
    std::fprintf(stderr, "essaim run: watching %zu file(s) for changes (Ctrl-C ends)\n", watcher.Files().size());
    std::vector<std::string> changed;
    while (!g_interrupted && !watcher.WaitForChange(1000, &changed)) {
    }
    if (g_interrupted) return kExitOk;
    std::fprintf(stderr, "essaim run: %s changed, running again\n", changed.front().c_str());
  }
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

CommandMain AddRunCommand(CLI::App& app) {
  auto r = std::make_shared<RunArgs>();
  CLI::App* sub = app.add_subcommand("run", "run an experiment");
  AddExperimentOptions(sub, r.get());
  sub->add_option("-o,--out", r->out, "output folder (default runs/<name>-<seed>)")->type_name("DIR");
  sub->add_flag("-q,--quiet", r->quiet, "no progress line, no summary");
  sub->add_flag("--strict", r->strict,
                "unknown attributes in the file are errors (exit 2); the first controller error ends the run, "
                "a parameter no script read fails it (exit 1)");
  sub->add_flag("--log-prefix", r->log_prefix, "start each log line with its tick and robot: [t=120 fb7] ...");
  sub->add_option("--log-dir", r->log_dir, "write each robot's log lines to DIR/<robot id>.log instead")
      ->type_name("DIR");
  sub->add_flag("--sandbox", r->sandbox,
                "untrusted scripts: no io/os/debug/native code, every instruction counted (docs/sandbox.md)");
  auto budget = std::make_shared<double>(-1);
  sub->add_option("--lua-budget", *budget, "instructions per call into Lua (default 1e9; 0 = unlimited)")
      ->type_name("N")
      ->check(CLI::Validator(
          [](std::string& v) -> std::string {
            auto d = ParseDouble(v);  // 1e9 is welcome
            if (d && *d >= 0 && *d < 9e18 && *d == std::floor(*d)) return "";
            return "'" + v + "' must be a non-negative integer (instructions per call; 0 = unlimited)";
          },
          ""));
  sub->add_option("--lua-memory", r->lua_memory_mib, "MiB per Lua state (default 256; 0 = unlimited)")
      ->type_name("MIB")
      ->check(IntegerIn(0, 1LL << 30, "0 = unlimited"));
  sub->add_option("--lua-seconds", r->lua_seconds, "wall clock per call into Lua (default 60; 0 = unlimited)")
      ->type_name("S")
      ->check(CLI::Range(0.0, 1e6));
  sub->add_option("--record", r->record, "also write recording.bin: every tick, or --record=every=N")
      ->type_name("[every=N]")
      ->expected(0, 1)
      ->check(RecordEvery());
  sub->add_flag("--watch", r->watch,
                "run again whenever the experiment's files (arena, scripts, modules, floor image) change; Ctrl-C ends");
  sub->add_option("--memory-log", r->memory_log_every,
                  "also write memory.csv: resident set and Lua bytes every N ticks (long runs, soak tests)")
      ->type_name("N")
      ->check(IntegerIn(1, kMaxTicks));
  sub->footer("Example:\n  essaim run arenas/foraging.argos --ticks 600 --seed 7 --record --set controllers.foraging.params.EPSILONGREED=0.3");
  return [r, sub, budget] {
    if (*budget >= 0) r->lua_budget = static_cast<long long>(*budget);
    r->record_every = 0;
    if (sub->count("--record") > 0) r->record_every = r->record.empty() ? 1 : static_cast<uint32_t>(std::stoul(r->record.substr(6)));
    if (r->watch) return WatchAndRun(*r);
    std::vector<std::string> inputs;
    return Run(*r, &inputs);
  };
}

}  // namespace essaim
