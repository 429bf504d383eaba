// `essaim run` and `essaim check`.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>

#include "app/commands.h"
#include "core/strings.h"
#include "model/xml_loader.h"
#include "output/atomic_file.h"
#include "output/recording.h"
#include "output/run_end.h"
#include "output/summary.h"
#include "sim/step.h"

namespace essaim {

namespace {
std::atomic<bool> g_interrupted{false};
void OnSigint(int) { g_interrupted = true; }

struct RunArgs {
  std::string file;
  std::string out;
  LoadOptions load;
  bool quiet = false, strict = false, sandbox = false;
  uint32_t record_every = 0;  // --record: a frame every N ticks (0: no recording)
};

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
  opt.lua.sandbox = r.sandbox;
  opt.lua.memory_limit = 64u << 20;
  opt.lua.instruction_limit = 100000000;
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
  std::signal(SIGINT, OnSigint);
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
  Json metrics;
  bool has_metrics = false;
  EndRun(*world, status, &info, &metrics, &has_metrics);
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
  if (info.status == "interrupted") return 130;
  if (status == StepStatus::Failed || info.status == "failed") return kExitRunFailed;
  if (r.strict && !world->controller_errors.empty()) return kExitRunFailed;
  return kExitOk;
}

}  // namespace essaim
