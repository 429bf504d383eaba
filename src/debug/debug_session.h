// One `essaim debug` session on the simulation's side: the client's requests served before
// the run (initialize, launch, breakpoints, configurationDone), between ticks (pause, new
// breakpoints) and while a thread is stopped (stack, scopes, variables, evaluate, set,
// stepping); the stops at tick boundaries (pause, entry, run to tick) and in Lua (through
// lua/debug's hook). One thread: a stop inside a robot's hook serves the client until a resume.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/value.h"
#include "debug/checkpoints.h"
#include "debug/dap_channel.h"
#include "debug/debug_front.h"
#include "debug/debug_view.h"
#include "lua/debug/lua_debugger.h"

namespace essaim {

class World;

/// What the launch request tells the session, once the command line made its model.
struct DebugLaunch {
  std::string experiment_dir;          // canonical: relative breakpoint paths start here
  std::vector<std::string> scripts;    // canonical: controllers' and Lua loop functions'
  std::vector<std::string> robot_ids;  // model order: thread i + 2
  bool lua_loop_functions = false;     // thread 1 exists
  bool stop_on_entry = false;
};

class DebugSession : public DebugListener {
 public:
  /// `launch` loads the experiment the launch request names (its arguments) into `*out`;
  /// false with the message for the client.
  using Launcher = std::function<bool(const Value& arguments, DebugLaunch* out, std::string* error)>;
  DebugSession(DapChannel& channel, Launcher launcher);

  /// Serves the client until configurationDone (true) or until it goes (false).
  bool Configure();
  /// Whether the last launch request failed: a session that ends before its run then
  /// ends as bad input (exit 2), as `essaim run` on the same file.
  bool LaunchFailed() const { return launch_failed_; }
  LuaDebugger& Debugger() { return debugger_; }
  /// The World once made (its states are attached as they open); null after it goes.
  void SetWorld(World* world) { world_ = world; }
  /// At the boundary before tick world.tick + 1: requests served, the stops there made.
  /// False: the client asked to end the run.
  bool BeforeTick(World& world);
  /// A log line of the run, as an output event.
  void LogLine(char stream, const std::string& line);
  /// summary.json's "debug": the divergences.
  Value Record() const;
  /// From now on checkpoints are taken, so that stepBack, reverseContinue and runToTick
  /// can go back (this process is a simulation forked by the front `front`).
  void EnableGoingBack(pid_t front, const FrontLink& link);
  /// The live page's scenes and frames go to `fd` (essaim debug --serve), from this
  /// process and the copies that go back.
  void ServeView(int fd) { view_.Open(fd); }
  /// The run's last tick is done (its world still there): the live page's last frame.
  void RunFinished() { PublishView(false, true); }
  /// Ends the checkpoints (the run is over).
  void EndCheckpoints();
  /// The run ended with `exit_code`: exited and terminated events, then the client's
  /// disconnect awaited (a few seconds at most).
  void Ended(int exit_code);

  // DebugListener
  void Stopped(int thread, lua_State* L, const StopInfo& why) override;
  void Console(const std::string& text) override;
  bool Fired(const RunPosition& where) override;

 private:
  enum class After { Stay, Resume };
  struct Stop {
    bool active = false;
    bool boundary = false;
    int thread = 0;
    lua_State* L = nullptr;
    int first_level = 0;
    std::string reason;
  };
  /// A going back under way in this process: re-simulating silently from a checkpoint to
  /// the target (kind "boundary", "entry", "fire"), or searching for the last breakpoint hit
  /// before (tick, fire) (kind "search").
  struct Replay {
    bool active = false;
    std::string kind;
    RunPosition at;  // the target, or where the search ends
    int thread = 0;
    std::string reason, description;
    long long from_tick = 0;  // the checkpoint's boundary
    bool found = false;
    RunPosition found_at;    // a search's last hit so far
    size_t divergences = 0;  // how many the process that went back had
  };
  struct Handle {
    enum class Kind { Locals, Upvalues, Globals, Table } kind;
    int thread = 0;
    int level = -1;
    int ref = -1;
  };

  After Dispatch(const Value& request);
  void ConfigurationDone(const Value& request);
  void ServePending();
  void BoundaryStops(const World& world);
  void ServeStopped();
  void BoundaryStop(const std::string& reason, int thread, const std::string& description);
  void SendStopped(const std::string& reason, int thread, const std::string& description, const std::string& text);
  void Release();

  // Requests, one function each (debug_requests.cpp).
  void Initialize(const Value& request);
  void Launch(const Value& request);
  void SetBreakpoints(const Value& request);
  std::vector<LineBreakpoint> ApplyBreakpoints(const Value& arguments, std::string* file);
  std::vector<FunctionBreakpoint> ApplyFunctionBreakpoints(const Value& arguments);
  bool ApplyExceptionBreakpoints(const Value& arguments);
  void SetFunctionBreakpoints(const Value& request);
  void SetExceptionBreakpoints(const Value& request);
  void Threads(const Value& request);
  void StackTrace(const Value& request);
  void Scopes(const Value& request);
  void Variables(const Value& request);
  void Evaluate(const Value& request);
  void SetVariable(const Value& request);
  After Resume(const Value& request, StepMode mode);
  After RunToTick(const Value& request);
  void Pause(const Value& request);
  After Terminate(const Value& request);
  After Disconnect(const Value& request);
  void GoBack(const Value& request);
  // Going back (debug_going_back.cpp).
  Value OrderFor(const Replay& target) const;
  [[noreturn]] void GoTo(const Replay& target, long long checkpoint_tick);
  void TakeOrder(const std::string& order);
  void ConcludeSearch();
  void FinishReplay();
  bool ReplayBoundary();

  std::string FilePath(const std::string& path) const;
  bool FileRuns(const std::string& canonical) const;
  lua_State* StateFor(int thread, int level) const;
  int NewHandle(Handle h);
  Value VariableJson(int thread, const struct LuaVariable& v);
  std::string ThreadName(int thread) const;
  long long BoundaryTick() const;
  /// A frame for the live page: the world now, paused or running (or ended), the selected
  /// thread.
  void PublishView(bool paused, bool ended = false);

  DapChannel& channel_;
  Launcher launcher_;
  LuaDebugger debugger_;
  DebugLaunch launch_;
  World* world_ = nullptr;
  bool configured_ = false;
  bool launched_ = false;
  bool launch_failed_ = false;  // the last launch request was refused (bad input)
  bool terminate_ = false;
  bool detached_ = false;
  int pause_thread_ = 0;  // a pause asked while running (thread), or 0
  long long run_to_tick_ = 0;
  Stop stop_;
  int last_thread_ = 0;
  std::vector<Handle> handles_;  // variablesReference - 1
  int next_breakpoint_id_ = 1;
  std::vector<Value> divergences_;
  std::unique_ptr<Checkpoints> checkpoints_;
  FrontLink front_;
  Replay replay_;
  ViewPublisher view_;
  std::map<std::string, Value> asked_breakpoints_;  // by source path as asked: the request's arguments
  Value asked_functions_, asked_exceptions_;
};

}  // namespace essaim
