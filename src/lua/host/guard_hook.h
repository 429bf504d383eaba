// What the guard's pieces (allocator, hook, libraries, watchdog thread) share inside
// lua/host; not for the rest of the code.
#pragma once
#include <cstddef>
#include <string>

#include "lua/host/lua_guard.h"

namespace essaim {

// The hook runs every kHookEvery instructions: the budget is checked to this precision,
// and the per-instruction cost stays one decrement in the VM.
constexpr int kHookEvery = 1000;

/// Lua's allocator for every guarded state; `ud` is the LuaGuard.
void* GuardedAlloc(void* ud, void* ptr, size_t osize, size_t nsize);

/// The count hook: budget, interrupts, wall clock, os.exit.
void GuardHook(lua_State* L, lua_Debug*);

/// The guard of a state made by NewGuardedState (the allocator's user data).
LuaGuard* GuardOf(lua_State* L);

/// From now on the hook fires at every instruction, of this coroutine and of the state's
/// main thread, so a pcall around the loop cannot swallow the stop.
void HookEveryInstruction(lua_State* L, LuaGuard* g);

/// "file:line" of the first Lua function up the stack of L (C functions have no line).
/// lua_getinfo with "Sl" neither allocates nor collects: safe inside the allocator.
bool ScriptLine(lua_State* L, char* out, size_t size);

/// One look at a state from the watchdog thread, `now` in steady-clock nanoseconds: arms
/// the hook of a long call, flags wall-clock overruns and `interrupt`. Returns the
/// stuck-in-C message the first time the call has been inside a C function for another
/// full limit, else "".
std::string WatchGuard(LuaGuard* g, long long now, bool interrupt);

long long SteadyNowNs();

/// With a library's fresh table on top of the stack (named `name`, as luaopen_* made it),
/// closes its escapes from the watchdog (coroutine, os, debug) and routes io's writes to stdout.
/// `base_error`: the stack index of the base library's own error().
void GuardLibrary(lua_State* L, const char* name, int base_error);

/// With io's fresh table on top: io.write and the file method write wrapped so that what
/// reaches the process's stdout goes to the guard's stdout_lines (none set: nothing done).
void RouteIoWrites(lua_State* L);

/// Under globals (and package.loaded) table, string, package, coroutine, utf8, io, os and
/// debug (io, os and debug not under the sandbox): empty tables that open their library
/// into themselves, guarded, at the first read, write or pairs(); `require` opens package
/// at its first call.
void DeclareLazyLibraries(lua_State* L, bool sandbox);

/// Whether the value at `index` is such a table, not opened yet. Runs no metamethod.
bool IsUnopenedLibrary(lua_State* L, int index);

/// Puts `prefix` before the path of the package table at `package`.
void PrependPackagePath(lua_State* L, int package, const std::string& prefix);

}  // namespace essaim
