#include "app/run_session.h"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdio>

#include "app/crash_signals.h"
#include "app/run_args.h"
#include "app/run_workdir.h"
#include "core/paths.h"
#include "output/atomic_file.h"
#include "output/recording.h"
#include "output/summary.h"
#include "sim/stepping.h"
#include "sim/world.h"

namespace essaim {

namespace {
// The session whose run is in progress, for the crash handler (which takes no argument).
std::atomic<RunSession*> g_crashing_session{nullptr};
}  // namespace

RunSession::RunSession() : watchdog([this](const std::string& message) { OnStuck(message); }), signals(&watchdog) {}

void RunSession::Begin(const std::string& out, const RunArgs& args, const Model& model) {
  std::lock_guard<std::mutex> lock(mutex_);
  out_ = out;
  args_ = &args;
  model_ = &model;
  signals.Listen();
  g_crashing_session = this;
  CatchCrashSignals(OnCrashSignal);
}

void RunSession::SetWorld(const World* world, RecordingWriter* recorder) {
  std::lock_guard<std::mutex> lock(mutex_);
  world_ = world;
  recorder_ = recorder;
}

void RunSession::SetWorkdir(RunWorkdir* workdir) {
  std::lock_guard<std::mutex> lock(mutex_);
  workdir_ = workdir;
}

void RunSession::End() {
  std::lock_guard<std::mutex> lock(mutex_);
  ReleaseCrashSignals();
  g_crashing_session = nullptr;
  out_.clear();
  args_ = nullptr;
  model_ = nullptr;
  world_ = nullptr;
  recorder_ = nullptr;
  workdir_ = nullptr;
}

void RunSession::OnStuck(const std::string& message) {
  std::lock_guard<std::mutex> lock(mutex_);
  WriteStoppedSummary(message, nullptr);
  ExitStuck(message);
}

void RunSession::OnCrashSignal(int sig) {
  if (RunSession* session = g_crashing_session.load()) session->OnCrash(sig);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

namespace {
// Who was running on the faulting thread, as the report names it.
std::string WhoCrashed(const Stepping& s, const RunInfo::Crash& crash) {
  if (s.robot >= 0) return "robot " + crash.robot + ": its controller";
  if (s.robot == kSteppingLoopFunctions) return "the loop functions";
  return "essaim itself, outside any controller or loop function (a bug: please report it)";
}
}  // namespace

// Not async-signal-safe: formatting and writing the summary allocate. A process whose heap
// the crash corrupted may hang here instead, so an alarm ends it (SIGALRM) after 10 s.
void RunSession::OnCrash(int sig) {
  alarm(10);
  const Stepping s = ThisThreadStepping();
  RunInfo::Crash crash;
  crash.signal = CrashSignalName(sig);
  crash.call = s.call;
  const Model* model = world_ ? &world_->model : model_;
  if (model && s.robot >= 0 && static_cast<size_t>(s.robot) < model->robots.size())
    crash.robot = model->robots[static_cast<size_t>(s.robot)].id;
  crash.tick = world_ ? world_->tick : 0;
  const std::string message = WhoCrashed(s, crash) + " crashed the process in " + (*s.call ? s.call : "a step") +
                              " at tick " + std::to_string(crash.tick) + ": " + crash.signal +
                              "; the run stopped there (docs/sandbox.md)";
  const bool locked = mutex_.try_lock();  // the faulting thread may hold it: write anyway
  WriteStoppedSummary(message, &crash);
  if (locked) mutex_.unlock();
  std::fprintf(stderr, "essaim: %s\n", message.c_str());
  std::fflush(stderr);
  _exit(3);
}

// What a run stopped for good leaves: summary.json (status failed, or crashed), the frames
// recorded so far sealed, the files the robots wrote listed.
void RunSession::WriteStoppedSummary(const std::string& message, const RunInfo::Crash* crash) {
  std::string error;
  if (!world_) {  // stuck in the loading or init() of a script
    if (args_)
      WriteFailureSummary(out_, ESSAIM_VERSION, args_->file, args_->load.overrides, model_, /*inputs=*/nullptr, message,
                          &error);
    if (workdir_) workdir_->Collect("");  // the view removed; the files written so far stay
    return;
  }
  RunInfo info;
  info.version = ESSAIM_VERSION;
  info.status = crash ? "crashed" : "failed";
  info.finished_by = "error";
  info.outputs = {"summary.json"};
  // The frames written so far end at a whole tick: sealed as they are, never left as a
  // temporary file.
  if (recorder_ && recorder_->IsOpen() && recorder_->Seal(&error)) info.outputs.push_back(kRecordingFile);
  info.failure = message;
  if (crash) info.crashed = true, info.crash = *crash;
  if (workdir_) {  // the robots may still write: only what nobody changed is removed
    info.files = workdir_->Collect(std::string(kRunFilesFolder) + "/");
    info.files_listed = true;
  }
  WriteFileAtomic(JoinPath(out_, "summary.json"), SummaryJsonText(*world_, info), &error);
}

}  // namespace essaim
