// The watchdog every lua_State runs under, controllers and loop functions alike
// (docs/sandbox.md): a memory cap in the allocator, an instruction budget per call counted
// by a count hook, interrupt requests (signals, the wall-clock monitor) seen by the same
// hook, and the sandbox's library set.
//
// Lua 5.4 pays for a count hook at every instruction (the VM's trap path), whatever the
// count: ~65% more Lua time on the foraging benchmark. So by default the hook is armed
// only when a call has run kArmAfterSeconds (by the run's Watchdog thread); a normal step
// never pays. Under --sandbox it is armed from the start and counts every instruction.
#pragma once
#include <atomic>
#include <cstddef>
#include <mutex>
#include <string>
#include <vector>

#include "lua/host/small_block_pool.h"

struct lua_State;
struct lua_Debug;
typedef int (*lua_CFunction)(lua_State* L);

namespace essaim {

class CompiledScripts;
class InputFiles;
class Watchdog;
struct WatchSlot;
struct WrittenLines;
struct LuaGuard;

/// A debugger attached to a run's states (lua/debug implements it; essaim debug makes one):
/// told of each state as it opens and closes, given the line and call events of the states
/// it hooks (SetDebugMask) and each uncaught error at the raising point, before unwinding.
class LuaDebugAttach {
 public:
  virtual ~LuaDebugAttach() = default;
  virtual void StateOpened(lua_State* L, LuaGuard* guard) = 0;
  virtual void StateClosed(LuaGuard* guard) = 0;
  virtual void Hook(lua_State* L, lua_Debug* ar) = 0;
  virtual void Raised(lua_State* L, const char* message) = 0;
};

/// The watchdog's limits, on by default (--lua-budget, --lua-init-budget, --lua-memory, <system>).
/// A call running this long gets the count hook (and, after a signal, is interrupted). Short,
/// as what runs before it is not counted: a swarm stuck in step() pays it once a robot.
constexpr double kArmAfterSeconds = 0.02;

/// Instructions a call may run before it is stopped: a step() (or a loop-function step hook)
/// runs every tick, so a stuck swarm must end in seconds; setup calls may do more work once.
constexpr long long kDefaultStepBudget = 100000000;    // ~0.3 s of Lua
constexpr long long kDefaultSetupBudget = 1000000000;  // ~3 s of Lua

/// Which budget a call runs under.
enum class CallKind {
  Step,   // step(), filling the readings, loop functions' pre_step/post_step and per-tick hooks
  Setup,  // a script's top level, init(), reset(), destroy(), post_experiment()
};

struct LuaOptions {
  bool sandbox = false;                                     // no io, os, debug, loadlib, C modules, bytecode
  size_t memory_limit = size_t{256} << 20;                  // bytes per state; 0 = unlimited
  long long instruction_limit = kDefaultStepBudget;         // per step call; 0 = unlimited
  long long setup_instruction_limit = kDefaultSetupBudget;  // per setup call; 0 = unlimited
  double wall_seconds = 60;                                 // per call, backstop for time in C functions; 0 = off
  InputFiles* inputs = nullptr;                             // where `require` lists the files it loads; null: nowhere
  /// The run's monitor thread (arms long calls, wall clock, interrupts, stuck calls). Null:
  /// the World makes its own; a state made with none is never watched.
  Watchdog* watchdog = nullptr;
  /// Where controller scripts are compiled once and shared; null: each state parses its file.
  CompiledScripts* scripts = nullptr;
  /// essaim debug's debugger; null in every other run.
  LuaDebugAttach* debugger = nullptr;
};

/// One state's accounting. Its address is the allocator's user data: never moved.
struct LuaGuard {
  // Memory.
  size_t bytes = 0;
  size_t peak = 0;
  size_t limit = 0;
  size_t allocations = 0;  // number of (re)allocations, for the no-churn test
  SmallBlockPool pool;     // where the state's small blocks live
  bool memory_exceeded = false;
  char memory_where[160] = "";  // "foo.lua:12", the script line that hit the limit
  // Instructions, counted per call; 0 = unlimited.
  long long step_budget = 0, setup_budget = 0;
  long long budget = 0;  // the running call's
  CallKind kind = CallKind::Step;
  long long used = 0;
  bool budget_exceeded = false;
  bool stopped = false;            // the guard raised a stop in this call: message handlers are skipped
  std::string exit_called;         // "os.exit called at foo.lua:12": the run must end
  bool always_armed = false;       // --sandbox: hooked from the first instruction
  std::atomic<bool> armed{false};  // the count hook is installed
  std::string name;                // "robot fb3" or "loop functions", for the stuck-in-C message
  // --sandbox: the folders `require` may load from, whatever package.path says; made
  // canonical at the first `require` (two realpath calls were ~4 µs of a state's set-up).
  std::vector<std::string> require_roots;
  bool require_roots_canonical = false;
  // What the package library gets when it opens (at first use): the sandbox's searchers,
  // the script's folder before package.path, the recording of required files.
  bool sandbox = false;
  std::string package_path_prefix;
  InputFiles* module_inputs = nullptr;
  // Where print and the io library's writes to the process's stdout go (RouteStdout); null:
  // to stdout, as Lua's. io.write and the file method write are wrapped when io opens.
  WrittenLines* stdout_lines = nullptr;
  // Where the libraries' own Lua text is compiled once for the run; null: per state.
  CompiledScripts* scripts = nullptr;
  // The library functions the guarded ones wrap, called directly: kept out of the Lua
  // state, so that debug.getupvalue cannot hand a script the original.
  lua_CFunction original_setmetatable = nullptr, original_debug_setmetatable = nullptr, original_xpcall = nullptr;
  lua_CFunction original_io_write = nullptr, original_file_write = nullptr;
  // Wall clock: the watchdog thread reads these while the owner's thread runs Lua.
  lua_State* state = nullptr;
  Watchdog* watchdog = nullptr;  // the one that watches this state's calls, or null
  // During a call: the calling thread's slot in the watchdog, and what it held before
  // (a guarded call made from inside another one).
  WatchSlot* slot = nullptr;
  LuaGuard* outer = nullptr;
  double wall_seconds = 0;
  // The running call's number (0: not inside a call). A number, not a start time: a clock
  // read per call was two per robot-step (~1 % of a trivial controller's); the watchdog
  // times a call from the passes that first see its number (WatchGuard).
  long long calls = 0;  // calls begun (owner's thread only)
  std::atomic<long long> call{0};
  long long watched_call = 0;     // watchdog thread only: the call its passes time,
  long long watched_seen_ns = 0;  // first seen running at this pass
  std::atomic<bool> wall_exceeded{false};
  std::atomic<bool> interrupted{false};     // a signal arrived while this call was stuck
  std::atomic<bool> stuck_reported{false};  // the watchdog reported this call stuck in C
  // Where a long call was last seen ("foo.lua:12"), for the stuck-in-C message: the hook
  // records it once the watchdog asks (calls over a second), so normal calls pay nothing.
  std::atomic<bool> track_where{false};
  char where[128] = "";  // under thread_mutex
  // The coroutine being resumed (null: the main thread), so that the watchdog arms the
  // thread that actually runs: hooks are per coroutine.
  std::mutex thread_mutex;
  lua_State* running = nullptr;
  // essaim debug: the debugger and the events it asks for (LUA_MASKLINE, LUA_MASKCALL);
  // its hook shares the state's one hook with the guard's count (InstallHook).
  LuaDebugAttach* debugger = nullptr;
  int debug_mask = 0;
};

/// A new state whose allocator is `guard`'s, with the hook installed (budget, interrupts).
/// Its calls are watched by options.watchdog (if any); close it with CloseGuardedState.
lua_State* NewGuardedState(LuaGuard* guard, const LuaOptions& options);
void CloseGuardedState(LuaGuard* guard);

/// The standard libraries, with what would escape the watchdog closed in every mode:
/// debug.sethook refused, __gc finalizers refused (Lua runs them with hooks off), xpcall
/// message handlers skipped once the guard stopped the call, os.exit ending the run as an
/// error. Under the sandbox, also without anything that reaches files, processes, native
/// code or bytecode. base and math are opened; table, string, package, coroutine, io, os,
/// utf8 and debug are opened at their first use (docs/sandbox.md says what differs).
void OpenGuardedLibraries(lua_State* L, bool sandbox);

/// Under the sandbox, `require` loads only files inside these folders (and below): the
/// arena's folder and the script's own. Symlinks and ".." are resolved (at the first
/// `require`) before the check.
void SetRequireRoots(LuaGuard* guard, const std::vector<std::string>& folders);

/// Brackets one call into Lua: resets the budget (`kind`'s), arms the wall clock and puts the
/// state in this thread's watchdog slot.
void BeginGuardedCall(LuaGuard* guard, CallKind kind);
/// Ends the call. When the guard stopped it (or a limit was hit and caught inside the
/// script), returns the reason ("memory limit exceeded (256 MiB per Lua state)", ...),
/// else "". `status` is lua_pcall's result.
std::string EndGuardedCall(LuaGuard* guard, int status);

/// Installs the state's one hook for what it needs now: the debugger's events (debug_mask),
/// the guard's count when armed. On `L` (the state or one of its coroutines).
void InstallHook(LuaGuard* guard, lua_State* L);
/// The debugger's events for this state from now on (0: none).
void SetDebugMask(LuaGuard* guard, int mask);
/// The debugger (if any) sees an uncaught error at its raising point: called by the
/// message handlers of controllers and loop functions.
void TellDebuggerRaised(lua_State* L, const char* message);

/// Under the sandbox, an error that met a nil io, os, debug, dofile or loadfile ("attempt
/// to index a nil value (global 'io')") says why, at the end of its first line.
void AddSandboxHint(const LuaGuard& g, std::string* message);

/// Whether EndGuardedCall's message already starts with the script's file:line (os.exit,
/// the memory limit), so the caller need not name the script.
inline bool StopNamesItsLine(const LuaGuard& g) { return !g.exit_called.empty() || g.memory_where[0] != '\0'; }

}  // namespace essaim
