// `essaim run`: one run as a short sequence of named steps (parse, load the model, open
// the output folder, build the world, open the outputs, step, finish, report), and --watch.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <vector>

#include "app/cli_support.h"
#include "app/commands.h"
#include "app/log_printer.h"
#include "app/run_args.h"
#include "app/run_command.h"
#include "app/run_report.h"
#include "app/run_session.h"
#include "app/run_workdir.h"
#include "core/paths.h"
#include "core/stopwatch.h"
#include "core/strings.h"
#include "output/memory_log.h"
#include "output/out_folder.h"
#include "output/recording.h"
#include "output/summary.h"
#include "serve/experiment_inputs.h"
#include "serve/file_watcher.h"
#include "sim/error_groups.h"
#include "sim/run_end.h"
#include "sim/step.h"

namespace essaim {

namespace {
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

// --lua-budget and --lua-init-budget: instructions per call; 1e9 is welcome.
CLI::Validator InstructionCount() {
  return CLI::Validator(
      [](std::string& v) -> std::string {
        auto d = ParseDouble(v);
        if (d && *d >= 0 && *d < 9e18 && *d == std::floor(*d)) return "";
        return "'" + v + "' must be a non-negative integer (instructions per call; 0 = unlimited)";
      },
      "");
}

std::string DefaultOutDir(const Model& m) {
  std::filesystem::path name = std::filesystem::path(m.file).filename();
  if (name.extension() == ".argos") name = name.stem();
  return "runs/" + name.string() + "-" + std::to_string(m.experiment.seed);
}

/// The folder will hold this run's outputs only: an earlier run's go into previous/, and
/// stderr says which.
bool SetAsideEarlierOutputsAndSay(const std::string& out, std::string* error) {
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
int FailedBeforeRun(RunSession& session, const RunArgs& r, const std::string& out, const Model* model,
                    const std::string& message, int code, const InputFiles* inputs = nullptr) {
  std::string error;
  if (out.empty()) return code;
  if (!PrepareOutFolder(out, &error) || (!session.out_lock.Held() && !session.out_lock.Acquire(out, &error)) ||
      (!session.earlier_set_aside && !SetAsideEarlierOutputsAndSay(out, &error)) ||
      !WriteFailureSummary(out, ESSAIM_VERSION, r.file, r.load.overrides, model, inputs, message, &error))
    std::fprintf(stderr, "essaim run: %s\n", error.c_str());
  return code;
}

/// A run whose world exists but that cannot go on (an output that cannot be opened):
/// summary.json with status "failed" and the message, exit 1.
int FailedRun(World& world, const std::string& out, const std::string& message) {
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

/// The options applied and the model loaded; else the exit code (with summary.json where
/// --out says, when it says).
std::optional<int> LoadModel(RunSession& session, RunArgs& r, std::unique_ptr<Model>* model) {
  std::string error;
  if (!ApplyOptions(&r, &error)) {
    std::fprintf(stderr, "essaim run: %s\n", error.c_str());
    return FailedBeforeRun(session, r, r.out, nullptr, error, kExitBadInput);
  }
  *model = LoadOrReport(r, &error);
  if (!*model) return FailedBeforeRun(session, r, r.out, nullptr, error, kExitBadInput);
  return std::nullopt;
}

/// Before any script runs: a wrong --out, or one another run is writing, is bad input. An
/// earlier run's outputs are set aside at once: the scripts write into files/ from their
/// first line.
bool OpenOutFolder(RunSession& session, const std::string& out) {
  std::string error;
  if (PrepareOutFolder(out, &error) && session.out_lock.Acquire(out, &error) &&
      SetAsideEarlierOutputsAndSay(out, &error)) {
    session.earlier_set_aside = true;
    return true;
  }
  std::fprintf(stderr, "essaim run: %s\n", error.c_str());
  return false;
}

/// The run's working folder, <out>/files/ (run_workdir.h); false with the message printed
/// and in `error`.
bool EnterWorkdir(RunWorkdir& workdir, const std::string& out, const Model& model, std::string* error) {
  std::string warning;
  if (!workdir.Enter(JoinPath(out, kRunFilesFolder), model.file, {out}, &warning, error)) {
    std::fprintf(stderr, "essaim run: %s\n", error->c_str());
    return false;
  }
  if (!warning.empty()) std::fprintf(stderr, "essaim run: warning: %s\n", warning.c_str());
  return true;
}

bool PrepareLogs(LogPrinter& logs) {
  std::string error;
  if (logs.Prepare(&error)) return true;
  std::fprintf(stderr, "essaim run: --log-dir: %s\n", error.c_str());
  return false;
}

/// The World's options: the watchdog's limits and the session's watchdog, log lines to `logs`.
SimOptions MakeSimOptions(RunSession& session, const RunArgs& r, const Model& model, const std::string& out,
                          const std::shared_ptr<LogPrinter>& logs) {
  SimOptions opt;
  opt.output_dir = out;
  opt.strict = r.strict;
  opt.lua = WatchdogOptions(model, r);
  opt.lua.watchdog = &session.watchdog;
  opt.inputs = std::make_shared<InputFiles>();  // kept when a script fails to load
  // Named as from here, the folder the run starts in, not from the view in out/files it works in.
  std::error_code ec;
  opt.inputs->SetBase(std::filesystem::current_path(ec).string());
  opt.log_sink = [logs](char stream, const std::string& line, const LogOrigin& from) {
    logs->Print(stream, line, from);
  };
  return opt;
}

/// One run once its model is loaded: what it owns, in the order it is made.
struct ActiveRun {
  ActiveRun(RunSession& s, const RunArgs& a, const Model& m, std::string o, std::string shown, RunWorkdir& w,
            LogPrinter& l)
      : session(s), args(a), model(m), out(std::move(o)), shown_out(std::move(shown)), workdir(w), logs(l) {}
  ~ActiveRun() { session.SetWorld(nullptr, nullptr); }  // before the world and the recorder go
  ActiveRun(const ActiveRun&) = delete;
  ActiveRun& operator=(const ActiveRun&) = delete;

  RunSession& session;
  const RunArgs& args;
  const Model& model;
  const std::string out;        // absolute: the run works in out/files
  const std::string shown_out;  // as given, for messages
  RunWorkdir& workdir;
  LogPrinter& logs;
  const RunHooks* hooks = nullptr;
  std::chrono::steady_clock::time_point start;
  std::unique_ptr<World> world;
  RecordingWriter recorder;
  MemoryLog memory_log;
  RunInfo info;
};

/// The World, its controllers' and loop functions' init() run; the folder cleared of an
/// earlier run's outputs. Else the exit code.
std::optional<int> BuildWorld(ActiveRun& run, const SimOptions& options, std::vector<std::string>* inputs) {
  std::string error;
  run.start = std::chrono::steady_clock::now();
  run.world = World::Create(run.model, options, &error);
  if (!run.world) {  // a script that does not load, or one a signal stopped while it loaded
    std::fprintf(stderr, "%s\n", error.c_str());
    if (run.hooks && run.hooks->error) run.hooks->error(error);
    const int signal = run.session.signals.Caught();
    return FailedBeforeRun(run.session, run.args, run.out, &run.model, error, signal ? 128 + signal : kExitBadInput,
                           options.inputs.get());
  }
  *inputs = ExperimentInputs(run.model, run.world.get());
  return std::nullopt;
}

/// The recording and memory.csv. A recording that cannot be written (a full disk) does not
/// stop the run: the other outputs are still written, and the run ends with exit 1.
std::optional<int> OpenOutputs(ActiveRun& run) {
  std::string error;
  run.info.version = ESSAIM_VERSION;
  if (run.args.record_every > 0 &&
      !run.recorder.Open(JoinPath(run.out, kRecordingFile), *run.world, run.args.record_every, &error))
    std::fprintf(stderr, "essaim run: %s; the run goes on without a recording\n", error.c_str());
  if (run.args.memory_log_every > 0 &&
      !run.memory_log.Open(JoinPath(run.out, kMemoryLogFile), run.args.memory_log_every, &error))
    return FailedRun(*run.world, run.out, error);
  run.session.SetWorld(run.world.get(), &run.recorder);
  return std::nullopt;
}

void RecordTick(ActiveRun& run, Progress& progress) {
  if (!run.recorder.IsOpen()) return;
  run.recorder.Record(*run.world);
  if (run.recorder.IsOpen()) return;
  progress.Finish();
  std::fprintf(stderr, "essaim run: %s at tick %llu; the run goes on without a recording\n",
               run.recorder.Failure().c_str(), static_cast<unsigned long long>(run.world->tick));
}

void MarkInterrupted(RunInfo* info) {
  info->status = "interrupted";
  info->finished_by = "interrupted";
}

/// Steps until the run finishes, fails or a signal comes; each tick recorded and its
/// memory sampled.
StepStatus StepUntilDone(ActiveRun& run) {
  World& world = *run.world;
  Progress progress(!run.args.quiet && isatty(STDERR_FILENO), run.model.experiment.length_ticks,
                    run.model.robots.size());
  run.logs.SetProgress(&progress);
  StepStatus status = StepStatus::Running;
  if (LengthReached(world)) status = StepStatus::Finished;
  if (!world.failure.empty()) status = StepStatus::Failed;  // init() failed
  while (status == StepStatus::Running) {
    if (run.session.signals.Caught()) {
      MarkInterrupted(&run.info);
      break;
    }
    if (run.hooks && run.hooks->before_tick && !run.hooks->before_tick(world)) {
      status = StepStatus::Finished;
      break;
    }
    status = Step(world);
    RecordTick(run, progress);
    run.memory_log.Sample(world);
    progress.Update(world.tick);
  }
  progress.Finish();
  run.logs.SetProgress(nullptr);
  if (run.session.signals.Caught() && status == StepStatus::Failed) {
    // A loop-function hook stopped by the signal: the run was interrupted, not broken.
    MarkInterrupted(&run.info);
    status = StepStatus::Running;
    world.failure.clear();
  }
  return status;
}

/// The recording ends with the run, however it ended (interrupted and failed runs too).
void CloseStreams(ActiveRun& run) {
  std::string error;
  if (run.args.record_every > 0) {
    if (run.recorder.Finish(*run.world, &error))
      run.info.outputs.push_back(kRecordingFile);
    else
      run.info.output_errors.push_back(error);
  }
  if (run.memory_log.IsOpen()) {
    if (run.memory_log.Close(&error))
      run.info.outputs.push_back(kMemoryLogFile);
    else
      run.info.output_errors.push_back(error);
  }
}

int ExitCode(const ActiveRun& run, StepStatus status) {
  const World& world = *run.world;
  if (run.info.status == "interrupted")
    return 128 + (run.session.signals.Caught() ? run.session.signals.Caught() : SIGINT);
  if (status == StepStatus::Failed || run.info.status == "failed") return kExitRunFailed;
  if (run.args.strict && (!world.controller_errors.empty() || !world.unread_params.empty())) return kExitRunFailed;
  return kExitOk;
}

/// What went wrong on stderr, the run's line on stdout; the exit code.
int Report(const ActiveRun& run, StepStatus status, const std::vector<std::string>& unwritten) {
  const World& world = *run.world;
  if (!world.failure.empty()) std::fprintf(stderr, "essaim run: %s\n", world.failure.c_str());
  if (!world.failure.empty() && run.hooks && run.hooks->error) run.hooks->error(world.failure);
  std::fputs(FormatUnreadParams(world.unread_params, run.args.strict).c_str(), stderr);
  if (!unwritten.empty()) {
    for (const std::string& e : unwritten) std::fprintf(stderr, "essaim run: %s\n", e.c_str());
    std::fprintf(stderr, "essaim run: the outputs in %s are incomplete%s\n", run.shown_out.c_str(),
                 FileExists(JoinPath(run.out, "summary.json")) ? "; summary.json lists those written" : "");
    if (run.info.status != "interrupted") return kExitRunFailed;
  }
  if (!run.args.quiet) {
    const double seconds = run.info.wall_seconds;
    const double steps = static_cast<double>(world.robot_steps);
    std::printf("essaim: %llu ticks, %zu robots, %.2f s, %.0f robot-steps/s; %zu controller error(s); output in %s\n",
                static_cast<unsigned long long>(world.tick), world.robots.size(), seconds,
                seconds > 0 ? steps / seconds : 0.0, world.controller_errors.size(), run.shown_out.c_str());
  }
  return ExitCode(run, status);
}

/// Ends the run (final Lua hooks, metrics), closes and writes every output; the exit code.
int FinishAndReport(ActiveRun& run, StepStatus status) {
  Value metrics;
  bool has_metrics = false;
  EndRun(*run.world, status, &run.info, &metrics, &has_metrics);
  std::string error;
  if (!run.logs.Flush(&error)) std::fprintf(stderr, "essaim run: --log-dir: %s\n", error.c_str());
  run.info.wall_seconds = SecondsSince(run.start);
  CloseStreams(run);
  run.info.files = run.workdir.Collect(std::string(kRunFilesFolder) + "/");
  run.info.files_listed = true;
  if (run.hooks && run.hooks->finishing) run.hooks->finishing(&run.info);
  std::vector<std::string> unwritten = run.info.output_errors;
  if (!WriteRunOutputs(run.out, *run.world, run.info, has_metrics ? &metrics : nullptr, &error))
    unwritten.push_back(error);  // metrics, time series or summary
  return Report(run, status, unwritten);
}

}  // namespace

/// One run. `inputs` receives the files it read (to watch) as soon as they are known.
int RunExperiment(RunSession& session, RunArgs& r, std::vector<std::string>* inputs, const RunHooks* hooks) {
  session.earlier_set_aside = false;
  r.file = NamedFromBelow(r.file);
  std::unique_ptr<Model> model;
  if (std::optional<int> code = LoadModel(session, r, &model)) return *code;
  AnchorPathsAbove(model.get());
  *inputs = ExperimentInputs(*model, nullptr);
  const std::string shown_out = r.out.empty() ? DefaultOutDir(*model) : r.out;
  if (!OpenOutFolder(session, shown_out)) return kExitBadInput;
  const std::string out = WeaklyCanonicalPath(shown_out);
  if (!r.log_dir.empty()) r.log_dir = WeaklyCanonicalPath(r.log_dir);  // read after the run enters out/files
  auto logs = std::make_shared<LogPrinter>(*model, r.log_prefix, r.log_dir);
  if (!PrepareLogs(*logs)) return kExitBadInput;
  SimOptions options = MakeSimOptions(session, r, *model, out, logs);
  if (hooks && hooks->options) hooks->options(&options);
  // Signals and the watchdog's last resort are handled from before init(): a controller
  // stuck there still ends the run with its outputs.
  RunWorkdir workdir;  // left after the world goes (C++ Destroy may write), and after the session forgets it
  SessionRun watched(session, out, r, *model);  // declared before the world, so it goes after it
  std::string error;
  if (!EnterWorkdir(workdir, out, *model, &error))
    return FailedBeforeRun(session, r, out, model.get(), error, kExitRunFailed);
  session.SetWorkdir(&workdir);  // until SessionRun ends
  ActiveRun run(session, r, *model, out, shown_out, workdir, *logs);
  run.hooks = hooks;
  if (std::optional<int> code = BuildWorld(run, options, inputs)) return *code;
  if (std::optional<int> code = OpenOutputs(run)) return *code;
  const StepStatus status = StepUntilDone(run);
  return FinishAndReport(run, status);
}

namespace {
/// --watch: run, then wait for a change to a file the run read, and run again, until
/// Ctrl-C (exit 0; a run it interrupts still leaves whole outputs).
int WatchAndRun(RunSession& session, const RunArgs& args) {
  FileWatcher watcher;
  if (!watcher.Ok()) {
    std::fprintf(stderr, "essaim run: --watch: %s\n", watcher.Error().c_str());
    return kExitBadInput;
  }
  session.signals.Listen();
  // Every file any run read: a run that failed on a broken module no longer lists it, and
  // its fix must still be seen.
  std::set<std::string> watched = {args.file};
  while (true) {
    RunArgs r = args;  // each run applies --set-file and the options afresh
    std::vector<std::string> inputs;
    RunExperiment(session, r, &inputs, nullptr);
    std::fflush(stdout);
    if (session.signals.Caught()) return kExitOk;
    watched.insert(inputs.begin(), inputs.end());
    watcher.Watch({watched.begin(), watched.end()});
    if (!watcher.Error().empty()) std::fprintf(stderr, "essaim run: --watch: %s\n", watcher.Error().c_str());
    std::fprintf(stderr, "essaim run: watching %zu file(s) for changes (Ctrl-C ends)\n", watcher.Files().size());
    std::vector<std::string> changed;
    while (!session.signals.Caught() && !watcher.WaitForChange(1000, &changed)) {
    }
    if (session.signals.Caught()) return kExitOk;
    std::fprintf(stderr, "essaim run: %s changed, running again\n", changed.front().c_str());
  }
}
}  // namespace

void AddRunOptions(CLI::App* sub, RunArgs* r, RunOptionValues* v) {
  AddExperimentOptions(sub, r);
  sub->add_option("-o,--out", r->out, "output folder (default runs/<name>-<seed>)")->type_name("DIR");
  sub->add_flag("-q,--quiet", r->quiet,
                "no progress line, no end-of-run summary (warnings and errors are always printed)");
  sub->add_flag("--strict", r->strict,
                "unknown attributes in the file are errors (exit 2); the first controller error ends the run, "
                "a parameter no script read fails it (exit 1)");
  sub->add_flag("--log-prefix", r->log_prefix, "start each log line with its tick and robot: [t=120 fb7] ...");
  sub->add_option("--log-dir", r->log_dir, "write each robot's log lines to DIR/<robot id>.log instead")
      ->type_name("DIR");
  sub->add_flag("--sandbox", r->sandbox,
                "untrusted scripts: no io/os/debug/native code, every instruction counted (docs/sandbox.md)");
  sub->add_option("--lua-budget", v->budget,
                  "instructions per step() call and per-tick loop-function hook (default 1e8; 0 = unlimited)")
      ->type_name("N")
      ->check(InstructionCount());
  sub->add_option("--lua-init-budget", v->init_budget,
                  "instructions per script top level, init(), reset(), destroy() (default 1e9, or --lua-budget "
                  "when larger; 0 = unlimited)")
      ->type_name("N")
      ->check(InstructionCount());
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
}

void FinishRunOptions(CLI::App* sub, RunArgs* r, const RunOptionValues& v) {
  if (v.budget >= 0) r->lua_budget = static_cast<long long>(v.budget);
  if (v.init_budget >= 0) r->lua_init_budget = static_cast<long long>(v.init_budget);
  r->record_every = 0;
  if (sub->count("--record") > 0)
    r->record_every = r->record.empty() ? 1 : static_cast<uint32_t>(std::stoul(r->record.substr(6)));
}

CommandMain AddRunCommand(CLI::App& app) {
  auto r = std::make_shared<RunArgs>();
  auto v = std::make_shared<RunOptionValues>();
  CLI::App* sub = app.add_subcommand("run", "run an experiment");
  AddRunOptions(sub, r.get(), v.get());
  sub->footer(
      "Example:\n  essaim run arenas/foraging.argos --ticks 600 --seed 7 --record --set "
      "controllers.foraging.params.EPSILONGREED=0.3");
  return [r, sub, v] {
    FinishRunOptions(sub, r.get(), *v);
    RunSession session;
    if (r->watch) return WatchAndRun(session, *r);
    std::vector<std::string> inputs;
    return RunExperiment(session, *r, &inputs, nullptr);
  };
}

}  // namespace essaim
