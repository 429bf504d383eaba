// The Lua side of essaim debug: breakpoints by file and line (moved to the next line with
// code), conditions, hit counts and logpoints; function breakpoints on step/init/reset/destroy;
// break on error; stepping in, over and out by stack depth. One hook per state, set only
// where something is asked (lua_guard's InstallHook shares it with the watchdog's count):
// a run with no breakpoints and no stepping runs unhooked.
#pragma once
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "lua/host/lua_guard.h"

namespace essaim {

struct LineBreakpoint {
  int line = 0;               // as asked
  std::string condition;      // a Lua expression; "" = always
  std::string hit_condition;  // "N", ">=N", "%N" (and >N, ==N, <N, <=N); "" = every hit
  std::string log_message;    // not empty: a logpoint, with {expr} interpolated
  // Filled by SetBreakpoints:
  int actual_line = 0;  // the next line with code
  bool verified = false;
  std::string message;  // why not verified
  long long hits = 0;
};

struct FunctionBreakpoint {
  std::string name;  // step, init, reset, destroy
  std::string condition;
  std::string hit_condition;
  bool verified = false;
  std::string message;
  long long hits = 0;
};

enum class StepMode { None, In, Over, Out };

/// A place in the run, ordered as the run goes: the tick, then who runs within it (the loop
/// functions' pre_step, robots in model order, the loop functions' post_step), then the
/// breakpoints that thread fired so far in that tick. Going back compares positions.
struct RunPosition {
  long long tick = 0;
  long long slot = 0;  // the thread's place within the tick
  long long fire = 0;  // its breakpoints fired in the tick, from 1
  bool operator<(const RunPosition& o) const {
    if (tick != o.tick) return tick < o.tick;
    if (slot != o.slot) return slot < o.slot;
    return fire < o.fire;
  }
  bool operator==(const RunPosition& o) const { return tick == o.tick && slot == o.slot && fire == o.fire; }
};

/// Why a thread stopped, as DAP's "stopped" event says it.
struct StopInfo {
  std::string reason;  // breakpoint, function breakpoint, exception, step
  std::string description;
  std::string text;     // the error, for an exception
  int first_level = 0;  // the innermost Lua frame to show (an error's handler is C)
};

/// What the debugger needs from the session (src/debug) that owns it.
class DebugListener {
 public:
  virtual ~DebugListener() = default;
  /// Thread `thread` stopped inside a hook of `L`: serves the client until it resumes.
  virtual void Stopped(int thread, lua_State* L, const StopInfo& why) = 0;
  /// A logpoint's or a failed condition's text ("fb7 tick 42: ...\n").
  virtual void Console(const std::string& text) = 0;
  /// A breakpoint fired at `where`; true: stop there even while quiet (a going back's target).
  virtual bool Fired(const struct RunPosition& where) = 0;
};

class LuaDebugger : public LuaDebugAttach {
 public:
  explicit LuaDebugger(DebugListener* listener) : listener_(listener) {}

  struct Thread {
    int id = 0;
    std::string name;  // the robot's id, or "loop functions"
    LuaGuard* guard = nullptr;
    lua_State* L = nullptr;
    int pending_function = -1;             // a function breakpoint hit at its call: stop at its first line
    long long fires_tick = -1, fires = 0;  // breakpoints it fired in tick fires_tick
  };

  /// Thread ids by the guard's name ("robot fb7", "loop functions"), before states open.
  void SetThreadIds(std::map<std::string, int> ids) { ids_ = std::move(ids); }
  const Thread* FindThread(int id) const;
  std::vector<const Thread*> Threads() const;

  /// The folder the run's relative script paths start from (the run itself works in a view
  /// of it, in its output folder).
  void SetSourceBase(std::string folder) { source_base_ = std::move(folder); }
  /// A script's path as the client names it: canonical, relative ones from the source base.
  std::string CanonicalFile(const std::string& path) const;

  /// The tick log lines show now (conditions' `tick`, logpoints' prefix, stepping).
  void SetTick(long long tick) { tick_ = tick; }
  /// Where `thread` stands now in this tick: its slot and the breakpoints it fired so far.
  RunPosition PositionOf(int thread) const;
  /// Stops (reason "step") at the first line `thread` runs in tick `tick`, quiet or not.
  void SetEntryTarget(int thread, long long tick);
  /// The states are no longer watched (a forked copy has no watchdog thread).
  void ForgetWatchdog();
  long long Tick() const { return tick_; }

  /// Replaces `file`'s breakpoints (its canonical path); `runs`: a controller or loop function
  /// runs the file, else `why_not` is each one's message. Returns them with actual_line,
  /// verified and message filled.
  std::vector<LineBreakpoint> SetBreakpoints(const std::string& file, std::vector<LineBreakpoint> bps, bool runs,
                                             const std::string& why_not);
  std::vector<FunctionBreakpoint> SetFunctionBreakpoints(std::vector<FunctionBreakpoint> bps);
  void SetBreakOnError(bool on) { break_on_error_ = on; }
  /// Every line breakpoint, by file (for going back: their hits counted again).
  const std::map<std::string, std::vector<LineBreakpoint>>& Breakpoints() const { return breakpoints_; }

  /// Resumes: stepping `mode` from where `thread` stands in `L` (null: at a tick boundary),
  /// or None to run to the next breakpoint.
  void Resume(StepMode mode, int thread, lua_State* L);
  /// No more stops, ever (the client went away): hooks removed.
  void Detach();
  /// While true the hooks never stop (the session evaluates, or re-simulates silently).
  void SetQuiet(bool quiet) { quiet_ = quiet; }
  bool Quiet() const { return quiet_; }

  // LuaDebugAttach
  void StateOpened(lua_State* L, LuaGuard* guard) override;
  void StateClosed(LuaGuard* guard) override;
  void Hook(lua_State* L, lua_Debug* ar) override;
  void Raised(lua_State* L, const char* message) override;

 private:
  Thread* ThreadOf(lua_State* L);
  void UpdateMasks();
  int MaskFor(const Thread& t) const;
  void OnCall(lua_State* L, Thread* t);
  void OnLine(lua_State* L, lua_Debug* ar, Thread* t);
  bool StepDone(lua_State* L) const;
  /// The breakpoint at this line that fires (condition, hit count); logpoints print here.
  bool BreakpointFires(lua_State* L, const std::string& file, int line, Thread* t);
  bool ConditionHolds(lua_State* L, const std::string& condition, const Thread& t);
  const std::string& CanonicalSource(const char* source);
  void Stop(Thread* t, lua_State* L, StopInfo why);
  std::string Prefix(const Thread& t) const;
  long long SlotOf(int thread) const;

  DebugListener* listener_;
  std::map<std::string, int> ids_;
  std::unordered_map<LuaGuard*, Thread> threads_;
  std::map<std::string, std::vector<LineBreakpoint>> breakpoints_;  // by canonical file
  std::set<int> breakpoint_lines_;                                  // any file: a cheap first test
  std::vector<FunctionBreakpoint> function_breakpoints_;
  std::unordered_map<std::string, std::string> canonical_;  // "@path" -> canonical path
  std::string source_base_;
  bool break_on_error_ = false;
  bool quiet_ = false;
  bool detached_ = false;
  long long tick_ = 0;
  long long robots_ran_tick_ = -1;  // the last tick a robot thread was seen running
  int entry_thread_ = 0;
  long long entry_tick_ = 0;
  struct Stepping {
    StepMode mode = StepMode::None;
    int thread = 0;
    int depth = 0;
    long long tick = 0;
  } step_;
};

/// Whether `hits` passes a DAP hit condition ("N" and ">=N": from the Nth on; "%N": every
/// Nth; ">N", "==N", "<N", "<=N"). False with `error` when it does not parse.
bool HitConditionPasses(const std::string& condition, long long hits, bool* passes, std::string* error);

}  // namespace essaim
