// What `essaim run` owns for as long as it runs (one run, or every run of --watch): the
// watchdog of its Lua states, the signals that interrupt it, the lock on its output folder,
// and what the watchdog's last resort needs to write a summary.
#pragma once
#include <mutex>
#include <string>

#include "app/signals.h"
#include "lua/host/watchdog.h"
#include "output/out_folder.h"
#include "output/summary.h"

namespace essaim {

struct Model;
struct RunArgs;
class RecordingWriter;
class RunWorkdir;
class World;

class RunSession {
 public:
  RunSession();
  RunSession(const RunSession&) = delete;
  RunSession& operator=(const RunSession&) = delete;

  Watchdog watchdog;  // before `signals`, which interrupts it
  SignalCatcher signals;
  /// Held from before the first write into --out until the process ends.
  OutFolderLock out_lock;
  /// Whether this run has moved an earlier run's outputs out of --out already.
  bool earlier_set_aside = false;

  /// From before the scripts load to after the world goes: where a stuck call's summary goes.
  void Begin(const std::string& out, const RunArgs& args, const Model& model);
  /// The world and its recorder once they exist; null, null before they go.
  void SetWorld(const World* world, RecordingWriter* recorder);
  /// The run's working folder while the run is in it (null after): a stuck run's summary
  /// lists its files, the view removed.
  void SetWorkdir(RunWorkdir* workdir);
  void End();

 private:
  /// Called from the watchdog thread while robots may still be stepped: a best-effort
  /// summary, then the process ends (exit 1).
  void OnStuck(const std::string& message);
  /// A crash signal (a segfault in a C++ controller...) on the thread that faulted: a
  /// best-effort summary naming what was running and the tick, then the process ends (exit 3).
  static void OnCrashSignal(int sig);
  void OnCrash(int sig);
  void WriteStoppedSummary(const std::string& message, const RunInfo::Crash* crash);

  std::mutex mutex_;  // the run in progress below, against the watchdog thread
  std::string out_;
  const RunArgs* args_ = nullptr;
  const Model* model_ = nullptr;
  const World* world_ = nullptr;  // null while init() runs
  RecordingWriter* recorder_ = nullptr;
  RunWorkdir* workdir_ = nullptr;
};

/// Begin()..End() of one run, as a scope: declared before the world, so it ends after it.
class SessionRun {
 public:
  SessionRun(RunSession& session, const std::string& out, const RunArgs& args, const Model& model) : session_(session) {
    session_.Begin(out, args, model);
  }
  ~SessionRun() { session_.End(); }
  SessionRun(const SessionRun&) = delete;
  SessionRun& operator=(const SessionRun&) = delete;

 private:
  RunSession& session_;
};

}  // namespace essaim
