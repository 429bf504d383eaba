#include "lua/host/lua_host.h"

#include <lua.hpp>

#include "core/paths.h"
#include "lua/host/guard_hook.h"
#include "lua/host/watchdog.h"

namespace essaim {

lua_State* NewGuardedState(LuaGuard* guard, const LuaOptions& options) {
  guard->limit = options.memory_limit;
  guard->step_budget = options.instruction_limit;
  guard->setup_budget = options.setup_instruction_limit;
  guard->wall_seconds = options.wall_seconds;
  guard->scripts = options.scripts;
  lua_State* L = lua_newstate(GuardedAlloc, guard);
  guard->state = L;
  if (!L) return nullptr;
  if (options.sandbox) {
    // Every instruction counted, in every coroutine (they inherit the hook).
    guard->always_armed = true;
    guard->armed = true;
    lua_sethook(L, GuardHook, LUA_MASKCOUNT, kHookEvery);
  }
  guard->watchdog = options.watchdog;
  if (options.debugger) {
    guard->debugger = options.debugger;
    options.debugger->StateOpened(L, guard);
  }
  return L;
}

void CloseGuardedState(LuaGuard* guard) {
  if (!guard->state) return;
  if (guard->watchdog) guard->watchdog->Forget(guard);
  if (guard->debugger) guard->debugger->StateClosed(guard);
  guard->debugger = nullptr;
  guard->watchdog = nullptr;
  lua_close(guard->state);
  guard->state = nullptr;
  guard->pool.Release();  // every block was freed by lua_close
}

lua_State* NewStockState() { return luaL_newstate(); }

void SeedMathRandom(lua_State* L, uint64_t seed, int64_t index) {
  lua_getglobal(L, "math");
  lua_getfield(L, -1, "randomseed");
  lua_pushinteger(L, static_cast<lua_Integer>(seed & 0x7fffffffffffffffull));
  lua_pushinteger(L, static_cast<lua_Integer>(index));
  lua_call(L, 2, 0);
  lua_pop(L, 1);
}

void PrependScriptFolder(lua_State* L, const std::string& script) {
  const std::string dir = DirName(script);
  const std::string prefix = dir.empty() ? "./?.lua;./?/init.lua;" : dir + "/?.lua;" + dir + "/?/init.lua;";
  lua_getglobal(L, "package");
  if (IsUnopenedLibrary(L, -1)) {
    std::string& deferred = GuardOf(L)->package_path_prefix;
    deferred = prefix + deferred;
  } else {
    PrependPackagePath(L, lua_gettop(L), prefix);
  }
  lua_pop(L, 1);
}

}  // namespace essaim
