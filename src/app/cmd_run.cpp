// `essaim run` and `essaim check`.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>

#include "app/commands.h"
#include "core/strings.h"
#include "lua/lua_guard.h"
#include "model/xml_loader.h"
#include "output/atomic_file.h"
#include "output/recording.h"
#include "output/summary.h"
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

struct RunArgs {
  std::string file;
  std::string out;
  LoadOptions load;
  bool quiet = false, strict = false, sandbox = false;
  uint32_t record_every = 0;  // --record: a frame every N ticks (0: no recording)
  long long lua_budget = -1, lua_memory_mib = -1;  // -1: the experiment's or the default
  double lua_seconds = -1;                          // wall clock per Lua call; -1: default
};

// The run in progress, for the watchdog's last resort (a call stuck inside a C function).
struct RunInProgress {
  std::string out;
  const World* world = nullptr;
  RunInfo info;
};
RunInProgress g_run;

void OnLuaStuck(const std::string& message) {
  // Called from the monitor thread while robots may still be stepped: a best-effort summary.
  if (!g_run.world) return;
  RunInfo info = g_run.info;
  info.status = "failed";
  info.finished_by = "error";
  info.outputs = {"summary.json"};
  Json s = BuildSummary(*g_run.world, info);
  s.Set("failure", Json::String(message));
  std::string error;
  WriteFileAtomic(JoinPath(g_run.out, "summary.json"), s.Dump(), &error);
}

bool ParseRunArgs(const std::vector<std::string>& args, RunArgs* r, std::string* error) {
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](std::string* out) {
      size_t eq = a.find('=');
      if (eq != std::string::npos && a.rfind("--", 0) == 0 && a.compare(0, eq, "--set") != 0) {
        *out = a.substr(eq + 1);
        return true;
      }
      if (i + 1 >= args.size()) {
        *error = a + " needs a value";
        return false;
      }
      *out = args[++i];
      return true;
    };
    auto key = a.substr(0, a.find('='));
    std::string v;
    if (key == "--ticks" || key == "--seed" || key == "--threads") {
      if (!value(&v)) return false;
      auto n = ParseInt(v);
      if (!n || *n < 0 || (key == "--threads" && *n > 1024)) {
        *error = key + ": '" + v + "' must be a non-negative integer";
        return false;
      }
      if (key == "--ticks") r->load.ticks = *n;
      else if (key == "--seed") r->load.seed = *n;
      else r->load.threads = static_cast<int>(*n);
    } else if (key == "--lua-budget" || key == "--lua-memory") {
      if (!value(&v)) return false;
      auto n = ParseInt(v);
      if (auto d = ParseDouble(v); !n && d && *d >= 0 && *d < 9e18 && *d == std::floor(*d))
        n = static_cast<long long>(*d);  // --lua-budget 1e9
      if (!n || *n < 0 || (key == "--lua-memory" && *n > (1LL << 30))) {
        *error = key + ": '" + v + "' must be a non-negative integer (" +
                 (key == "--lua-budget" ? "instructions per call" : "MiB per Lua state") + "; 0 = unlimited)";
        return false;
      }
      (key == "--lua-budget" ? r->lua_budget : r->lua_memory_mib) = *n;
    } else if (key == "--lua-seconds") {
      if (!value(&v)) return false;
      auto d = ParseDouble(v);
      if (!d || !(*d >= 0 && *d <= 1e6)) {
        *error = "--lua-seconds: '" + v + "' must be a number of seconds between 0 and 1e6 (0 = no wall-clock limit)";
        return false;
      }
      r->lua_seconds = *d;
    } else if (a == "--set") {
      if (!value(&v)) return false;
      r->load.overrides.push_back(v);
    } else if (key == "--out" || key == "-o") {
      if (!value(&r->out)) return false;
    } else if (a == "--quiet" || a == "-q") {
      r->quiet = true;
    } else if (a == "--strict") {
      r->strict = true;
    } else if (a == "--sandbox") {
      r->sandbox = true;
    } else if (key == "--record") {
      // --record, --record every=N, --record=every=N
      if (a.size() > key.size()) v = a.substr(key.size() + 1);
      else if (i + 1 < args.size() && args[i + 1].rfind("every=", 0) == 0) v = args[++i];
      r->record_every = 1;
      if (!v.empty()) {
        auto n = v.rfind("every=", 0) == 0 ? ParseInt(v.substr(6)) : std::nullopt;
        if (!n || *n < 1 || *n > 1000000) {
          *error = "--record: '" + v + "' must be every=N with N a positive integer";
          return false;
        }
        r->record_every = static_cast<uint32_t>(*n);
      }
    } else if (!a.empty() && a[0] == '-') {
      *error = "unknown option " + a;
      return false;
    } else if (r->file.empty()) {
      r->file = a;
    } else {
      *error = "unexpected argument " + a;
      return false;
    }
  }
  if (r->file.empty()) {
    *error = "missing the experiment file (.argos)";
    return false;
  }
  return true;
}

std::unique_ptr<Model> LoadOrReport(const RunArgs& r) {
  ErrorList errors, warnings;
  auto model = LoadExperimentFile(r.file, r.load, &errors, &warnings);
  if (!r.quiet)
    for (const InputError& w : warnings.Items()) {
      ErrorList one;
      one.Add(w.file, w.line, w.element, "warning: " + w.message);
      std::fputs(one.Format().c_str(), stderr);
    }
  if (!model) std::fputs(errors.Format().c_str(), stderr);
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
  std::string name = m.file.substr(m.file.find_last_of('/') == std::string::npos ? 0 : m.file.find_last_of('/') + 1);
  if (name.size() > 6 && name.compare(name.size() - 6, 6, ".argos") == 0) name.resize(name.size() - 6);
  return "runs/" + name + "-" + std::to_string(m.experiment.seed);
}
}  // namespace

int CheckCommand(const std::vector<std::string>& args) {
  RunArgs r;
  std::string error;
  if (!ParseRunArgs(args, &r, &error)) {
    std::fprintf(stderr, "essaim check: %s\n", error.c_str());
    return kExitBadInput;
  }
  auto model = LoadOrReport(r);
  if (!model) return kExitBadInput;
  // Scripts too: load every controller and the loop functions without stepping.
  SimOptions opt;
  opt.output_dir = "";
  opt.lua = WatchdogOptions(*model, r);
  std::string err;
  auto world = World::Create(*model, opt, &err);
  if (!world) {
    std::fprintf(stderr, "%s\n", err.c_str());
    return kExitBadInput;
  }
  std::printf("%s: ok (%zu robots, %zu obstacles, %llu ticks)\n", r.file.c_str(), model->robots.size(),
              model->obstacles.size(), static_cast<unsigned long long>(model->experiment.length_ticks));
  return kExitOk;
}

int RunCommand(const std::vector<std::string>& args) {
  RunArgs r;
  std::string error;
  if (!ParseRunArgs(args, &r, &error)) {
    std::fprintf(stderr, "essaim run: %s\n", error.c_str());
    return kExitBadInput;
  }
  auto model = LoadOrReport(r);
  if (!model) return kExitBadInput;
  std::string out = r.out.empty() ? DefaultOutDir(*model) : r.out;
  if (!MakeDirs(out, &error)) {
    std::fprintf(stderr, "essaim run: %s\n", error.c_str());
    return kExitRunFailed;
  }

  SimOptions opt;
  opt.output_dir = out;
  opt.strict = r.strict;
  opt.lua = WatchdogOptions(*model, r);
  opt.log_sink = [](char stream, const std::string& line) {
    std::fprintf(stream == 'E' ? stderr : stdout, "%s\n", line.c_str());
  };
  auto t0 = std::chrono::steady_clock::now();
  auto world = World::Create(*model, opt, &error);
  if (!world) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return kExitBadInput;
  }
  RecordingWriter recorder;
  if (r.record_every > 0 && !recorder.Open(JoinPath(out, kRecordingFile), *world, r.record_every, &error)) {
    std::fprintf(stderr, "essaim run: %s\n", error.c_str());
    return kExitRunFailed;
  }
  g_run.out = out;
  g_run.world = world.get();
  g_run.info.version = ESSAIM_VERSION;
  SetLuaStuckHandler(OnLuaStuck);
  struct Forget {  // before the world goes
    ~Forget() {
      SetLuaStuckHandler(nullptr);
      g_run.world = nullptr;
    }
  } forget;
  std::signal(SIGINT, OnSignal);
  std::signal(SIGTERM, OnSignal);
  Progress progress(!r.quiet && isatty(STDERR_FILENO), model->experiment.length_ticks, model->robots.size());
  RunInfo info;
  info.version = ESSAIM_VERSION;
  StepStatus status = StepStatus::Running;
  if (LengthReached(*world)) status = StepStatus::Finished;
  while (status == StepStatus::Running) {
    if (g_interrupted) {
      info.status = "interrupted";
      info.finished_by = "interrupted";
      break;
    }
    status = Step(*world);
    if (recorder.IsOpen()) recorder.Record(*world);
    progress.Update(world->tick);
  }
  progress.Finish();
  if (g_interrupted && status == StepStatus::Failed) {
    // A loop-function hook stopped by the signal: the run was interrupted, not broken.
    info.status = "interrupted";
    info.finished_by = "interrupted";
    status = StepStatus::Running;
    world->failure.clear();
  }
  if (status == StepStatus::Failed) {
    info.status = world->controller_errors.empty() ? "failed" : "controller_error";
    info.finished_by = "error";
  } else if (world->finished_by_loop_functions) {
    info.finished_by = "loop_functions";
  }
  Json metrics;
  bool has_metrics = false;
  std::string finish_error;
  if (status != StepStatus::Failed && !FinishRun(*world, &metrics, &has_metrics, &finish_error)) {
    world->failure = finish_error;
    info.status = "failed";
  }
  if (info.status == "ok" && !world->controller_errors.empty()) info.status = "controller_error";
  info.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // The recording ends with the run, however it ended (interrupted and failed runs too).
  if (recorder.IsOpen()) {
    if (!recorder.Finish(*world, &error)) {
      std::fprintf(stderr, "essaim run: %s\n", error.c_str());
      return kExitRunFailed;
    }
    info.outputs.push_back(kRecordingFile);
  }
  if (!WriteRunOutputs(out, *world, info, has_metrics ? &metrics : nullptr, &error)) {
    std::fprintf(stderr, "essaim run: %s\n", error.c_str());
    return kExitRunFailed;
  }
  if (!world->failure.empty()) std::fprintf(stderr, "essaim run: %s\n", world->failure.c_str());
  if (!r.quiet) {
    double steps = static_cast<double>(world->tick) * model->robots.size();
    std::printf("essaim: %llu ticks, %zu robots, %.2f s, %.0f robot-steps/s; %zu controller error(s); output in %s\n",
                static_cast<unsigned long long>(world->tick), model->robots.size(), info.wall_seconds,
                info.wall_seconds > 0 ? steps / info.wall_seconds : 0.0, world->controller_errors.size(), out.c_str());
  }
  if (info.status == "interrupted") return 128 + (g_interrupted ? g_interrupted.load() : SIGINT);
  if (status == StepStatus::Failed || info.status == "failed") return kExitRunFailed;
  if (r.strict && !world->controller_errors.empty()) return kExitRunFailed;
  return kExitOk;
}

}  // namespace essaim
