#include "lua/lua_guard.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <thread>
#include <vector>

#include <lua.hpp>

#include "core/paths.h"

namespace essaim {

namespace {
// The hook runs every kHookEvery instructions: the budget is checked to this precision,
// and the per-instruction cost stays one decrement in the VM.
constexpr int kHookEvery = 1000;

std::atomic<bool> g_interrupt{false};
std::atomic<LuaStuckHandler> g_stuck_handler{nullptr};

long long NowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// "file:line" of the first Lua function up the stack of L (C functions have no line).
// lua_getinfo with "Sl" neither allocates nor collects: safe inside the allocator.
bool ScriptLine(lua_State* L, char* out, size_t size) {
  lua_Debug ar;
  for (int level = 0; level < 8 && lua_getstack(L, level, &ar); ++level) {
    if (lua_getinfo(L, "Sl", &ar) && ar.currentline > 0) {
      std::snprintf(out, size, "%s:%d", ar.short_src, ar.currentline);
      return true;
    }
  }
  return false;
}
// The Lua line that asked for memory over the limit, in the running coroutine.
void RecordMemoryWhere(LuaGuard* g) {
  lua_State* L = g->running ? g->running : g->state;
  if (L) ScriptLine(L, g->memory_where, sizeof g->memory_where);
}

// Everything but the two common cases below: large blocks, reallocations, an empty free
// list, the memory limit. Out of line, so that the fast path saves no registers.
[[gnu::noinline]] void* SlowAlloc(LuaGuard* g, void* ptr, size_t old, size_t nsize) {
  if (nsize == 0) {
    std::free(ptr);  // a large block
    g->bytes -= old;
    return nullptr;
  }
  if (g->limit && nsize > old && g->bytes - old + nsize > g->limit) {
    if (!g->memory_exceeded) RecordMemoryWhere(g);
    g->memory_exceeded = true;
    return nullptr;  // Lua raises "not enough memory"; the owner reports the limit
  }
  void* p = nullptr;
  if (SmallBlockPool::IsSmall(old) && SmallBlockPool::IsSmall(nsize) && SmallBlockPool::SameClass(old, nsize)) {
    p = ptr;  // fits where it is
  } else if (!SmallBlockPool::IsSmall(old) && !SmallBlockPool::IsSmall(nsize)) {
    p = std::realloc(ptr, nsize);  // large to large (or new large): malloc's realloc
  } else {
    // Moving between the pool and malloc, or between classes.
    p = SmallBlockPool::IsSmall(nsize) ? g->pool.Allocate(nsize) : std::malloc(nsize);
    if (p && ptr) {
      std::memcpy(p, ptr, std::min(old, nsize));
      if (SmallBlockPool::IsSmall(old)) g->pool.Free(ptr, old);
      else std::free(ptr);
    }
  }
  if (p) {
    g->bytes = g->bytes - old + nsize;
    g->peak = std::max(g->peak, g->bytes);
    ++g->allocations;
  }
  return p;
}

// Lua's allocator for every guarded state. Lua's objects are mostly small and short-lived:
// most calls free a small block or take a new one, which the pool's free lists serve
// without a call. The accounting (bytes, peak, allocations) is the same on every path.
void* GuardedAlloc(void* ud, void* ptr, size_t osize, size_t nsize) {
  auto* g = static_cast<LuaGuard*>(ud);
  const size_t old = ptr ? osize : 0;  // with no block, Lua passes the object's type
  if (nsize == 0) {
    if (!ptr) return nullptr;  // Lua "frees" the null array of every table without one
    if (!SmallBlockPool::IsSmall(old)) return SlowAlloc(g, ptr, old, nsize);
    g->pool.Free(ptr, old);
    g->bytes -= old;
    return nullptr;
  }
  if (!ptr && SmallBlockPool::IsSmall(nsize) && !(g->limit && g->bytes + nsize > g->limit)) {
    if (void* p = g->pool.TakeFree(nsize)) {
      g->bytes += nsize;
      g->peak = std::max(g->peak, g->bytes);
      ++g->allocations;
      return p;
    }
  }
  return SlowAlloc(g, ptr, old, nsize);
}

void GuardHook(lua_State* L, lua_Debug*);

LuaGuard* GuardOf(lua_State* L) {
  void* ud = nullptr;
  lua_getallocf(L, &ud);
  return static_cast<LuaGuard*>(ud);
}

/// From now on the hook fires at every instruction, of this coroutine and of the state's
/// main thread, so a pcall around the loop cannot swallow the stop.
void HookEveryInstruction(lua_State* L, LuaGuard* g) {
  lua_sethook(L, GuardHook, LUA_MASKCOUNT, 1);
  if (g->state && g->state != L) lua_sethook(g->state, GuardHook, LUA_MASKCOUNT, 1);
}

/// Raises `what` at the interrupted line; message handlers (xpcall) are skipped from now
/// on, as Lua would run them inside this hook, where hooks are off.
[[noreturn]] void Stop(lua_State* L, const char* what) {
  LuaGuard* g = GuardOf(L);
  g->stopped = true;
  HookEveryInstruction(L, g);
  lua_Debug ar;
  if (lua_getstack(L, 0, &ar) && lua_getinfo(L, "Sl", &ar) && ar.currentline > 0)
    lua_pushfstring(L, "%s:%d: %s", ar.short_src, ar.currentline, what);
  else
    lua_pushstring(L, what);
  lua_error(L);
  std::abort();  // lua_error does not return
}

// The running line, kept for the stuck-in-C message (only for calls the monitor flagged).
void RecordWhere(lua_State* L, LuaGuard* g) {
  lua_Debug ar;
  if (!lua_getstack(L, 0, &ar) || !lua_getinfo(L, "Sl", &ar) || ar.currentline <= 0) return;
  std::lock_guard<std::mutex> lock(g->thread_mutex);
  std::snprintf(g->where, sizeof g->where, "%s:%d", ar.short_src, ar.currentline);
}

void GuardHook(lua_State* L, lua_Debug*) {
  LuaGuard* g = GuardOf(L);
  if (!g->exit_called.empty()) Stop(L, g->exit_called.c_str());
  // lua_gethookcount: a coroutine stopped earlier may count every instruction.
  if (g->budget > 0 && (g->budget_exceeded || (g->used += lua_gethookcount(L)) > g->budget)) {
    g->budget_exceeded = true;
    char what[96];
    std::snprintf(what, sizeof what, "instruction budget exceeded (%lld instructions per call, --lua-budget)", g->budget);
    Stop(L, what);
  }
  if (g->interrupted.load(std::memory_order_relaxed)) Stop(L, "interrupted by a signal");
  if (g->wall_exceeded.load(std::memory_order_relaxed)) {
    char what[96];
    std::snprintf(what, sizeof what, "wall-clock limit exceeded (%g s per call)", g->wall_seconds);
    Stop(L, what);
  }
  if (g->track_where.load(std::memory_order_relaxed)) RecordWhere(L, g);
}

// The monitor: one thread for the process, started with the first state. It arms the
// hook of calls that run long, flags wall-clock overruns and signals. Leaked on purpose,
// so that it outlives static destructors at exit.
struct Monitor {
  std::mutex mutex;
  std::vector<LuaGuard*> guards;
};

void Watch(LuaGuard* g, long long now) {
  const long long start = g->call_started_ns.load(std::memory_order_relaxed);
  if (start == 0) return;
  const double s = static_cast<double>(now - start) * 1e-9;
  if (s < kArmAfterSeconds) return;
  if (g_interrupt.load(std::memory_order_relaxed)) g->interrupted.store(true, std::memory_order_relaxed);
  if (g->wall_seconds > 0 && s > g->wall_seconds) g->wall_exceeded.store(true, std::memory_order_relaxed);
  if (s > 1) g->track_where.store(true, std::memory_order_relaxed);
  // Re-armed if it was cleared (debug.sethook is refused now; kept as a backstop). lua_sethook may be called
  // asynchronously (ldebug.c).
  if (lua_gethook(g->state) != GuardHook) {
    lua_sethook(g->state, GuardHook, LUA_MASKCOUNT, kHookEvery);
    g->armed.store(true, std::memory_order_relaxed);
  }
  {
    std::lock_guard<std::mutex> lock(g->thread_mutex);
    if (g->running && lua_gethook(g->running) != GuardHook) lua_sethook(g->running, GuardHook, LUA_MASKCOUNT, kHookEvery);
  }
  // No hook ran for another full limit: stuck inside a C function (a pathological
  // string.find), which cannot be unwound safely. Stop the process with a message.
  if (g->wall_seconds > 0 && s > 2 * g->wall_seconds + 1) {
    char where[sizeof g->where + 16] = "";
    {
      std::lock_guard<std::mutex> lock(g->thread_mutex);
      if (g->where[0]) std::snprintf(where, sizeof where, " (last at %s)", g->where);
    }
    char message[320];
    std::snprintf(message, sizeof message, "%s: stuck for %.0f s inside a C function called from Lua%s; stopping (exit 1)",
                  g->name.c_str(), s, where);
    if (LuaStuckHandler handler = g_stuck_handler.load()) handler(message);
    std::fprintf(stderr, "essaim: %s\n", message);
    std::fflush(stderr);
    _exit(1);
  }
}

Monitor& TheMonitor() {
  static Monitor* m = [] {
    auto* mon = new Monitor;
    std::thread([mon] {
      for (;;) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        std::lock_guard<std::mutex> lock(mon->mutex);
        const long long now = NowNs();
        for (LuaGuard* g : mon->guards) Watch(g, now);
      }
    }).detach();
    return mon;
  }();
  return *m;
}

// coroutine.resume, recording which coroutine runs (for the monitor) and handing it the
// hook when the call is already armed.
int GuardedResume(lua_State* L) {
  LuaGuard* g = GuardOf(L);
  lua_State* co = lua_tothread(L, 1);  // null: the original raises the usual error
  lua_State* previous;
  {
    std::lock_guard<std::mutex> lock(g->thread_mutex);
    previous = g->running;
    g->running = co;
  }
  if (co && lua_gethook(L) == GuardHook && lua_gethook(co) != GuardHook)
    lua_sethook(co, GuardHook, LUA_MASKCOUNT, kHookEvery);
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  const int status = lua_pcall(L, lua_gettop(L) - 1, LUA_MULTRET, 0);
  {
    std::lock_guard<std::mutex> lock(g->thread_mutex);
    g->running = previous;
  }
  if (status != LUA_OK) return lua_error(L);
  return lua_gettop(L);
}

// coroutine.wrap over the guarded resume; errors are re-raised with the caller's position,
// as the original's.
const char kGuardedWrap[] = R"(
local create, resume, error = coroutine.create, coroutine.resume, error
return function(f)
  local co = create(f)
  local function finish(ok, ...)
    if not ok then error((...), 2) end
    return ...
  end
  return function(...) return finish(resume(co, ...)) end
end
)";

void GuardCoroutines(lua_State* L) {
  lua_getglobal(L, "coroutine");
  lua_getfield(L, -1, "resume");
  lua_pushcclosure(L, GuardedResume, 1);
  lua_setfield(L, -2, "resume");
  if (luaL_loadbufferx(L, kGuardedWrap, sizeof kGuardedWrap - 1, "=coroutine.wrap", "t") == LUA_OK &&
      lua_pcall(L, 0, 1, 0) == LUA_OK)
    lua_setfield(L, -2, "wrap");
  else
    lua_pop(L, 1);
  lua_pop(L, 1);
}

int TextOnlyLoad(lua_State* L) {
  // load(chunk, chunkname, mode, env) with mode forced to "t": no bytecode in the sandbox.
  if (lua_gettop(L) < 3) lua_settop(L, 3);
  lua_pushliteral(L, "t");
  lua_replace(L, 3);
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, lua_gettop(L) - 1, LUA_MULTRET);
  return lua_gettop(L);
}
// package.searchers[2] under the sandbox: Lua files on package.path, as text only, and
// only inside the guard's require roots: a script cannot set package.path to read
// /etc/passwd through require's error messages.
std::string FindAllowedModule(lua_State* L, LuaGuard* g, const std::string& name, std::string* tried) {
  std::string file_name = name;
  std::replace(file_name.begin(), file_name.end(), '.', '/');
  lua_getglobal(L, "package");
  lua_getfield(L, -1, "path");
  const std::string path = lua_tostring(L, -1) ? lua_tostring(L, -1) : "";
  lua_pop(L, 2);
  for (size_t start = 0; start <= path.size();) {
    size_t end = path.find(';', start);
    if (end == std::string::npos) end = path.size();
    std::string candidate = path.substr(start, end - start);
    start = end + 1;
    if (candidate.empty()) continue;
    for (size_t q = candidate.find('?'); q != std::string::npos; q = candidate.find('?', q + file_name.size()))
      candidate.replace(q, 1, file_name);
    const std::string real = CanonicalPath(candidate);
    const bool allowed = !real.empty() && std::any_of(g->require_roots.begin(), g->require_roots.end(),
                                                      [&](const std::string& root) { return IsInsideFolder(real, root); });
    if (allowed && FileExists(real)) return candidate;
    *tried += std::string(tried->empty() ? "" : "\n\t") + "no file '" + candidate + "'" + (real.empty() ? "" : allowed ? "" : " (outside the arena's folder)");
  }
  return "";
}

int TextOnlyLuaSearcher(lua_State* L) {
  const char* name = luaL_checkstring(L, 1);
  bool failed = false;
  {  // the strings go before lua_error, whose longjmp skips C++ destructors
    std::string tried;
    const std::string filename = FindAllowedModule(L, GuardOf(L), name, &tried);
    if (filename.empty()) {
      lua_pushstring(L, tried.c_str());
      return 1;
    }
    failed = luaL_loadfilex(L, filename.c_str(), "t") != LUA_OK;
    if (failed) {
      luaL_where(L, 1);
      lua_pushfstring(L, "error loading module '%s' from file '%s':\n\t%s", name, filename.c_str(), lua_tostring(L, -2));
      lua_concat(L, 2);
    } else {
      lua_pushstring(L, filename.c_str());
    }
  }
  if (failed) return lua_error(L);
  return 2;
}
}  // namespace

void SetRequireRoots(LuaGuard* guard, const std::vector<std::string>& folders) {
  guard->require_roots.clear();
  for (const std::string& folder : folders) {
    std::string real = CanonicalPath(folder);
    if (!real.empty()) guard->require_roots.push_back(real);
  }
}

namespace {
// The library functions wrapped below, called directly (plain C functions, no upvalues):
// kept out of the Lua state, so that debug.getupvalue cannot hand a script the original.
std::atomic<lua_CFunction> g_setmetatable{nullptr}, g_debug_setmetatable{nullptr}, g_xpcall{nullptr};

// Lua runs __gc finalizers with hooks off, where no budget could stop a loop: refused.
bool RefuseFinalizer(lua_State* L) {
  if (lua_type(L, 2) != LUA_TTABLE) return false;
  lua_pushliteral(L, "__gc");
  const bool has_gc = lua_rawget(L, 2) != LUA_TNIL;
  lua_pop(L, 1);
  return has_gc;
}
int GuardedSetmetatable(lua_State* L) {
  if (RefuseFinalizer(L))
    return luaL_error(L, "setmetatable: a __gc finalizer is refused (Lua runs finalizers outside the watchdog)");
  return g_setmetatable.load()(L);
}
int GuardedDebugSetmetatable(lua_State* L) {
  if (RefuseFinalizer(L))
    return luaL_error(L, "debug.setmetatable: a __gc finalizer is refused (Lua runs finalizers outside the watchdog)");
  return g_debug_setmetatable.load()(L);
}

// An xpcall message handler, skipped once the guard stopped the call: Lua would run it
// inside the stopping hook, with hooks off.
int GuardedMessageHandler(lua_State* L) {
  if (GuardOf(L)->stopped) return 1;  // the stop's message, as it is
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, lua_gettop(L) - 1, 1);
  return 1;
}
int GuardedXpcall(lua_State* L) {
  luaL_checktype(L, 2, LUA_TFUNCTION);
  lua_pushvalue(L, 2);
  lua_pushcclosure(L, GuardedMessageHandler, 1);
  lua_replace(L, 2);
  return g_xpcall.load()(L);  // Lua's own xpcall, in this frame: yields still work
}

int RefusedSethook(lua_State* L) {
  return luaL_error(L, "debug.sethook is not available: the watchdog's hook cannot be replaced");
}

// os.exit ends the run as an error, never the process: essaim writes its outputs and
// chooses the exit code. Raised like a stop, so no pcall can swallow it.
int GuardedExit(lua_State* L) {
  LuaGuard* g = GuardOf(L);
  char where[160], what[192] = "os.exit called";
  if (ScriptLine(L, where, sizeof where)) std::snprintf(what, sizeof what, "os.exit called at %s", where);
  g->exit_called = what;
  g->stopped = true;
  HookEveryInstruction(L, g);
  lua_pushstring(L, what);
  return lua_error(L);
}

/// Replaces table[field] (the table on top of the stack) by `fn`, remembering the original.
void Wrap(lua_State* L, const char* field, lua_CFunction fn, std::atomic<lua_CFunction>* original) {
  lua_getfield(L, -1, field);
  if (original) original->store(lua_tocfunction(L, -1));
  lua_pop(L, 1);
  lua_pushcfunction(L, fn);
  lua_setfield(L, -2, field);
}

// Closes what escapes the watchdog, in every mode (the sandbox removes os and debug whole).
void CloseEscapes(lua_State* L) {
  lua_pushglobaltable(L);
  Wrap(L, "setmetatable", GuardedSetmetatable, &g_setmetatable);
  Wrap(L, "xpcall", GuardedXpcall, &g_xpcall);
  lua_pop(L, 1);
  if (lua_getglobal(L, "debug") == LUA_TTABLE) {
    Wrap(L, "setmetatable", GuardedDebugSetmetatable, &g_debug_setmetatable);
    Wrap(L, "sethook", RefusedSethook, nullptr);
  }
  lua_pop(L, 1);
  if (lua_getglobal(L, "os") == LUA_TTABLE) Wrap(L, "exit", GuardedExit, nullptr);
  lua_pop(L, 1);
}
}  // namespace

lua_State* NewGuardedState(LuaGuard* guard, const LuaOptions& options) {
  guard->limit = options.memory_limit;
  guard->budget = options.instruction_limit;
  guard->wall_seconds = options.wall_seconds;
  lua_State* L = lua_newstate(GuardedAlloc, guard);
  guard->state = L;
  if (!L) return nullptr;
  if (options.sandbox) {
    // Every instruction counted, in every coroutine (they inherit the hook).
    guard->always_armed = true;
    guard->armed = true;
    lua_sethook(L, GuardHook, LUA_MASKCOUNT, kHookEvery);
  }
  Monitor& m = TheMonitor();
  std::lock_guard<std::mutex> lock(m.mutex);
  m.guards.push_back(guard);
  return L;
}

void CloseGuardedState(LuaGuard* guard) {
  if (!guard->state) return;
  Monitor& m = TheMonitor();
  std::lock_guard<std::mutex> lock(m.mutex);
  m.guards.erase(std::remove(m.guards.begin(), m.guards.end(), guard), m.guards.end());
  lua_close(guard->state);
  guard->state = nullptr;
  guard->pool.Release();  // every block was freed by lua_close
}

void OpenGuardedLibraries(lua_State* L, bool sandbox) {
  luaL_openlibs(L);
  GuardCoroutines(L);
  CloseEscapes(L);
  if (!sandbox) return;
  for (const char* name : {"io", "os", "debug", "dofile", "loadfile"}) {
    lua_pushnil(L);
    lua_setglobal(L, name);
  }
  lua_getglobal(L, "package");
  const int package = lua_gettop(L);
  lua_getfield(L, package, "loaded");
  for (const char* name : {"io", "os", "debug"}) {
    lua_pushnil(L);
    lua_setfield(L, -2, name);
  }
  lua_pop(L, 1);
  lua_pushnil(L);
  lua_setfield(L, package, "loadlib");
  lua_pushliteral(L, "");
  lua_setfield(L, package, "cpath");
  // Keep the preload searcher and Lua files (as text); drop the two that load C libraries.
  lua_getfield(L, package, "searchers");
  lua_pushcfunction(L, TextOnlyLuaSearcher);
  lua_rawseti(L, -2, 2);
  lua_pushnil(L);
  lua_rawseti(L, -2, 4);
  lua_pushnil(L);
  lua_rawseti(L, -2, 3);
  lua_pop(L, 1);
  lua_pop(L, 1);
  lua_getglobal(L, "load");
  lua_pushcclosure(L, TextOnlyLoad, 1);
  lua_setglobal(L, "load");
}

void BeginGuardedCall(LuaGuard* g) {
  g->used = 0;
  g->budget_exceeded = false;
  g->stopped = false;
  if (g->track_where.load(std::memory_order_relaxed)) {
    g->track_where.store(false, std::memory_order_relaxed);
    std::lock_guard<std::mutex> lock(g->thread_mutex);
    g->where[0] = '\0';
  }
  g->wall_exceeded.store(false, std::memory_order_relaxed);
  g->interrupted.store(false, std::memory_order_relaxed);
  if (g->always_armed) {
    if (lua_gethookcount(g->state) != kHookEvery || lua_gethook(g->state) != GuardHook)
      lua_sethook(g->state, GuardHook, LUA_MASKCOUNT, kHookEvery);  // after a stop, or debug.sethook
  } else if (g->armed.load(std::memory_order_relaxed)) {
    lua_sethook(g->state, nullptr, 0, 0);  // the last call ran long; this one starts unhooked
    g->armed.store(false, std::memory_order_relaxed);
  }
  g->call_started_ns.store(NowNs(), std::memory_order_relaxed);
}

std::string EndGuardedCall(LuaGuard* g, int status) {
  g->call_started_ns.store(0, std::memory_order_relaxed);
  if (!g->exit_called.empty()) return g->exit_called;
  if (g->memory_exceeded) {
    char what[96];
    if (g->limit >= (size_t{1} << 20))
      std::snprintf(what, sizeof what, "memory limit exceeded (%zu MiB per Lua state, --lua-memory)", g->limit >> 20);
    else
      std::snprintf(what, sizeof what, "memory limit exceeded (%zu bytes per Lua state, --lua-memory)", g->limit);
    return g->memory_where[0] ? std::string(g->memory_where) + ": " + what : std::string(what);
  }
  // Limits hit but caught by the script's own pcall still stop it.
  if (status == LUA_OK && g->budget_exceeded) return "instruction budget exceeded (caught by the script)";
  if (status == LUA_OK && g->wall_exceeded.load(std::memory_order_relaxed)) return "wall-clock limit exceeded";
  return {};
}

void SetLuaStuckHandler(LuaStuckHandler handler) { g_stuck_handler.store(handler); }

void RequestLuaInterrupt() { g_interrupt.store(true, std::memory_order_relaxed); }

}  // namespace essaim
