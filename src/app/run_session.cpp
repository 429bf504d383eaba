#include "app/run_session.h"

#include "app/run_args.h"
#include "app/run_workdir.h"
#include "core/paths.h"
#include "output/atomic_file.h"
#include "output/recording.h"
#include "output/summary.h"
#include "sim/world.h"

namespace essaim {

RunSession::RunSession() : watchdog([this](const std::string& message) { OnStuck(message); }), signals(&watchdog) {}

void RunSession::Begin(const std::string& out, const RunArgs& args, const Model& model) {
  std::lock_guard<std::mutex> lock(mutex_);
  out_ = out;
  args_ = &args;
  model_ = &model;
  signals.Listen();
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
  out_.clear();
  args_ = nullptr;
  model_ = nullptr;
  world_ = nullptr;
  recorder_ = nullptr;
  workdir_ = nullptr;
}

void RunSession::OnStuck(const std::string& message) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::string error;
  if (!world_) {  // stuck in the loading or init() of a script
    if (args_)
      WriteFailureSummary(out_, ESSAIM_VERSION, args_->file, args_->load.overrides, model_, /*inputs=*/nullptr, message,
                          &error);
    if (workdir_) workdir_->Collect("");  // the view removed; the files written so far stay
    ExitStuck(message);
  }
  RunInfo info;
  info.version = ESSAIM_VERSION;
  info.status = "failed";
  info.finished_by = "error";
  info.outputs = {"summary.json"};
  // The frames written so far end at a whole tick: sealed as they are, never left as a
  // temporary file.
  if (recorder_ && recorder_->IsOpen() && recorder_->Seal(&error)) info.outputs.push_back(kRecordingFile);
  info.failure = message;
  if (workdir_) {  // the robots may still write: only what nobody changed is removed
    info.files = workdir_->Collect(std::string(kRunFilesFolder) + "/");
    info.files_listed = true;
  }
  WriteFileAtomic(JoinPath(out_, "summary.json"), SummaryJsonText(*world_, info), &error);
  ExitStuck(message);
}

}  // namespace essaim
