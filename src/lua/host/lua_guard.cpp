// The guard's count hook and the calls it brackets; what the watchdog thread does to one state.
#include "lua/host/lua_guard.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <lua.hpp>
#include <mutex>

#include "lua/host/guard_hook.h"
#include "lua/host/watchdog.h"

namespace essaim {

long long SteadyNowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

LuaGuard* GuardOf(lua_State* L) {
  void* ud = nullptr;
  lua_getallocf(L, &ud);
  return static_cast<LuaGuard*>(ud);
}

void HookEveryInstruction(lua_State* L, LuaGuard* g) {
  lua_sethook(L, GuardHook, LUA_MASKCOUNT, 1);
  if (g->state && g->state != L) lua_sethook(g->state, GuardHook, LUA_MASKCOUNT, 1);
}

namespace {
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

// The running line, kept for the stuck-in-C message (only for calls the watchdog flagged).
void RecordWhere(lua_State* L, LuaGuard* g) {
  lua_Debug ar;
  if (!lua_getstack(L, 0, &ar) || !lua_getinfo(L, "Sl", &ar) || ar.currentline <= 0) return;
  std::lock_guard<std::mutex> lock(g->thread_mutex);
  std::snprintf(g->where, sizeof g->where, "%s:%d", ar.short_src, ar.currentline);
}

// Installs the hook where it is missing: on the state and on the coroutine it resumes.
// Re-armed if it was cleared (debug.sethook is refused now; kept as a backstop).
// lua_sethook may be called asynchronously (ldebug.c).
void Arm(LuaGuard* g) {
  if (!(lua_gethookmask(g->state) & LUA_MASKCOUNT)) {
    g->armed.store(true, std::memory_order_relaxed);
    InstallHook(g, g->state);
  }
  std::lock_guard<std::mutex> lock(g->thread_mutex);
  if (g->running && !(lua_gethookmask(g->running) & LUA_MASKCOUNT)) InstallHook(g, g->running);
}

// The debugger's events and the guard's count through one hook.
void DebugDispatchHook(lua_State* L, lua_Debug* ar) {
  LuaGuard* g = GuardOf(L);
  if (ar->event == LUA_HOOKCOUNT) {
    GuardHook(L, ar);
    return;
  }
  if (g->debugger) g->debugger->Hook(L, ar);
}

std::string StuckMessage(LuaGuard* g, double seconds) {
  char where[sizeof g->where + 16] = "";
  {
    std::lock_guard<std::mutex> lock(g->thread_mutex);
    if (g->where[0]) std::snprintf(where, sizeof where, " (last at %s)", g->where);
  }
  char message[320];
  std::snprintf(message, sizeof message,
                "%s: stuck for %.0f s inside a C function called from Lua%s; stopping (exit 1)", g->name.c_str(),
                seconds, where);
  return message;
}
}  // namespace

void GuardHook(lua_State* L, lua_Debug*) {
  LuaGuard* g = GuardOf(L);
  if (!g->exit_called.empty()) Stop(L, g->exit_called.c_str());
  // lua_gethookcount: a coroutine stopped earlier may count every instruction.
  if (g->budget > 0 && (g->budget_exceeded || (g->used += lua_gethookcount(L)) > g->budget)) {
    g->budget_exceeded = true;
    char what[128];
    std::snprintf(what, sizeof what, "instruction budget exceeded (%lld instructions per call, %s)", g->budget,
                  g->kind == CallKind::Step ? "--lua-budget" : "--lua-init-budget");
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

std::string WatchGuard(LuaGuard* g, long long now, bool interrupt) {
  const long long call = g->call.load(std::memory_order_relaxed);
  if (call == 0) return {};
  if (call != g->watched_call) {  // first seen: it began since the previous pass
    g->watched_call = call;
    g->watched_seen_ns = now;
  }
  // Timed from the first pass that saw it: passes come at least 0.01 s apart, so the pass
  // that arms it is the one an exact start time would pick (or, after a late pass, the next);
  // a limit is never applied early.
  const double at_least = static_cast<double>(now - g->watched_seen_ns) * 1e-9;
  if (at_least < kArmAfterSeconds) return {};
  if (interrupt) g->interrupted.store(true, std::memory_order_relaxed);
  if (g->wall_seconds > 0 && at_least > g->wall_seconds) g->wall_exceeded.store(true, std::memory_order_relaxed);
  if (at_least > 1) g->track_where.store(true, std::memory_order_relaxed);
  Arm(g);
  // No hook ran for another full limit: stuck inside a C function (a pathological
  // string.find), which cannot be unwound safely.
  if (g->wall_seconds > 0 && at_least > 2 * g->wall_seconds + 1 && !g->stuck_reported.exchange(true))
    return StuckMessage(g, at_least);
  return {};
}

void BeginGuardedCall(LuaGuard* g, CallKind kind) {
  g->kind = kind;
  g->budget = kind == CallKind::Step ? g->step_budget : g->setup_budget;
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
  g->stuck_reported.store(false, std::memory_order_relaxed);
  if (g->always_armed) {
    if (lua_gethookcount(g->state) != kHookEvery || !(lua_gethookmask(g->state) & LUA_MASKCOUNT))
      InstallHook(g, g->state);  // after a stop, or debug.sethook
  } else if (g->armed.load(std::memory_order_relaxed)) {
    g->armed.store(false, std::memory_order_relaxed);
    InstallHook(g, g->state);  // the last call ran long; this one starts unhooked
  }
  g->call.store(++g->calls, std::memory_order_relaxed);
  if (g->watchdog) {
    g->slot = g->watchdog->ThisThreadSlot();
    g->outer = g->slot->guard.load(std::memory_order_relaxed);
    g->slot->guard.store(g, std::memory_order_release);
  }
}

void InstallHook(LuaGuard* g, lua_State* L) {
  const int count = g->armed.load(std::memory_order_relaxed) || g->always_armed ? LUA_MASKCOUNT : 0;
  if (g->debugger && g->debug_mask)
    lua_sethook(L, DebugDispatchHook, g->debug_mask | count, kHookEvery);
  else if (count)
    lua_sethook(L, GuardHook, LUA_MASKCOUNT, kHookEvery);
  else
    lua_sethook(L, nullptr, 0, 0);
}

void SetDebugMask(LuaGuard* g, int mask) {
  if (g->debug_mask == mask || !g->state) return;
  g->debug_mask = mask;
  InstallHook(g, g->state);
}

void TellDebuggerRaised(lua_State* L, const char* message) {
  LuaGuard* g = GuardOf(L);
  if (g && g->debugger) g->debugger->Raised(L, message);
}

std::string EndGuardedCall(LuaGuard* g, int status) {
  g->call.store(0, std::memory_order_relaxed);
  if (g->slot) {
    g->slot->guard.store(g->outer, std::memory_order_release);
    g->slot = nullptr;
    g->outer = nullptr;
  }
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

}  // namespace essaim
