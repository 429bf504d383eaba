// The standard libraries as guarded states see them: what would escape the watchdog closed
// in every mode, and under the sandbox nothing that reaches files, processes, native code
// or bytecode.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <lua.hpp>
#include <mutex>
#include <string>
#include <vector>

#include "core/paths.h"
#include "lua/host/compiled_scripts.h"
#include "lua/host/guard_hook.h"
#include "lua/host/lua_require.h"

namespace essaim {

namespace {
// coroutine.resume, recording which coroutine runs (for the watchdog) and handing it the
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
  if (co && lua_gethook(L) && (lua_gethook(co) != lua_gethook(L) || lua_gethookmask(co) != lua_gethookmask(L)))
    InstallHook(g, co);
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

// wrap's argument check: nil for a function, else Lua's message (luaL_typeerror's words).
int NotAFunction(lua_State* L) {
  if (lua_type(L, 1) == LUA_TFUNCTION) return 0;
  const char* got = lua_isnone(L, 1)                                   ? "no value"
                    : luaL_getmetafield(L, 1, "__name") == LUA_TSTRING ? lua_tostring(L, -1)
                    : lua_type(L, 1) == LUA_TLIGHTUSERDATA             ? "light userdata"
                                                                       : luaL_typename(L, 1);
  lua_pushfstring(L, "bad argument #1 to 'coroutine.wrap' (function expected, got %s)", got);
  return 1;
}

// coroutine.wrap over the guarded resume, as Lua 5.4's auxwrap: a non-function argument is
// wrap's bad argument, errors are re-raised with the caller's position, and a coroutine that
// died by an error has its pending to-be-closed variables closed first (an error there
// replaces the original).
const char kGuardedWrap[] = R"(
local create, resume, error, close, status, not_a_function = ...
return function(...)
  local bad = not_a_function(...)
  if bad then error(bad, 2) end
  local co = create(...)
  local function finish(ok, ...)
    if ok then return ... end
    local err = ...
    if status(co) == "dead" then
      local closed, closing_error = close(co)
      if not closed then err = closing_error end
    end
    error(err, 2)
  end
  return function(...) return finish(resume(co, ...)) end
end
)";

// With coroutine's table on top: resume and wrap guarded. The wrap's text is compiled
// once per run (when the state has the run's compiled scripts).
void GuardCoroutines(lua_State* L, int base_error) {
  lua_getfield(L, -1, "resume");
  lua_pushcclosure(L, GuardedResume, 1);
  lua_setfield(L, -2, "resume");
  const int coroutine = lua_gettop(L);
  // The wrap's upvalues: create, resume, error, close, status, the argument's check.
  for (const char* name : {"create", "resume"}) lua_getfield(L, coroutine, name);
  lua_pushvalue(L, base_error);
  for (const char* name : {"close", "status"}) lua_getfield(L, coroutine, name);
  lua_pushcfunction(L, NotAFunction);
  constexpr int kUpvalues = 6;
  CompiledScripts* scripts = GuardOf(L)->scripts;
  const int loaded = scripts ? scripts->LoadText(L, "=coroutine.wrap", kGuardedWrap, sizeof kGuardedWrap - 1)
                             : luaL_loadbufferx(L, kGuardedWrap, sizeof kGuardedWrap - 1, "=coroutine.wrap", "t");
  lua_insert(L, coroutine + 1);  // the chunk (or the error) under its upvalues
  if (loaded == LUA_OK && lua_pcall(L, kUpvalues, 1, 0) == LUA_OK)
    lua_setfield(L, coroutine, "wrap");
  else
    lua_settop(L, coroutine);
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

// require's roots, made canonical at the first require: two realpath calls per state were
// ~4 µs of its ~90 µs set-up.
void MakeRootsCanonical(LuaGuard* g) {
  std::vector<std::string> real;
  for (const std::string& folder : g->require_roots) {
    std::string canonical = CanonicalPath(folder);
    if (!canonical.empty()) real.push_back(std::move(canonical));
  }
  g->require_roots = std::move(real);
  g->require_roots_canonical = true;
}

// package.searchers[2] under the sandbox: Lua files on package.path, as text only, and
// only inside the guard's require roots: a script cannot set package.path to read
// /etc/passwd through require's error messages.
std::string FindAllowedModule(lua_State* L, LuaGuard* g, const std::string& name, std::string* tried) {
  if (!g->require_roots_canonical) MakeRootsCanonical(g);
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
    const bool allowed =
        !real.empty() && std::any_of(g->require_roots.begin(), g->require_roots.end(),
                                     [&](const std::string& root) { return IsInsideFolder(real, root); });
    if (allowed && FileExists(real)) return candidate;
    *tried += std::string(tried->empty() ? "" : "\n\t") + "no file '" + candidate + "'" +
              (real.empty() ? ""
               : allowed    ? ""
                            : " (outside the arena's folder)");
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
      lua_pushfstring(L, "error loading module '%s' from file '%s':\n\t%s", name, filename.c_str(),
                      lua_tostring(L, -2));
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
  guard->require_roots = folders;
  guard->require_roots_canonical = false;
}

namespace {

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
  return GuardOf(L)->original_setmetatable(L);
}
int GuardedDebugSetmetatable(lua_State* L) {
  if (RefuseFinalizer(L))
    return luaL_error(L, "debug.setmetatable: a __gc finalizer is refused (Lua runs finalizers outside the watchdog)");
  return GuardOf(L)->original_debug_setmetatable(L);
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
  return GuardOf(L)->original_xpcall(L);  // Lua's own xpcall, in this frame: yields still work
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
void Wrap(lua_State* L, const char* field, lua_CFunction fn, lua_CFunction* original) {
  lua_getfield(L, -1, field);
  if (original) *original = lua_tocfunction(L, -1);
  lua_pop(L, 1);
  lua_pushcfunction(L, fn);
  lua_setfield(L, -2, field);
}

// Closes what escapes the watchdog in the base library, in every mode.
void CloseBaseEscapes(lua_State* L) {
  LuaGuard* g = GuardOf(L);
  lua_pushglobaltable(L);
  Wrap(L, "setmetatable", GuardedSetmetatable, &g->original_setmetatable);
  Wrap(L, "xpcall", GuardedXpcall, &g->original_xpcall);
  lua_pop(L, 1);
}

// The sandbox's package (the table on top): no C libraries, Lua files as text from the
// allowed folders only.
void SandboxPackage(lua_State* L) {
  const int package = lua_gettop(L);
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
}

// With package's fresh table on top: what the host asked for before it opened.
void ReadyPackage(lua_State* L, const LuaGuard& g) {
  if (g.sandbox) SandboxPackage(L);
  if (g.module_inputs) WrapModuleSearcher(L, lua_gettop(L), g.module_inputs);
  if (!g.package_path_prefix.empty()) PrependPackagePath(L, lua_gettop(L), g.package_path_prefix);
}
}  // namespace

void GuardLibrary(lua_State* L, const char* name, int base_error) {
  LuaGuard* g = GuardOf(L);
  if (std::strcmp(name, LUA_COLIBNAME) == 0) {
    GuardCoroutines(L, base_error);
  } else if (std::strcmp(name, LUA_DBLIBNAME) == 0) {
    Wrap(L, "setmetatable", GuardedDebugSetmetatable, &g->original_debug_setmetatable);
    Wrap(L, "sethook", RefusedSethook, nullptr);
  } else if (std::strcmp(name, LUA_OSLIBNAME) == 0) {
    Wrap(L, "exit", GuardedExit, nullptr);
  } else if (std::strcmp(name, LUA_LOADLIBNAME) == 0) {
    ReadyPackage(L, *g);
  } else if (std::strcmp(name, LUA_IOLIBNAME) == 0) {
    RouteIoWrites(L);
  }
}

void AddSandboxHint(const LuaGuard& g, std::string* message) {
  if (!g.sandbox) return;
  const size_t end = std::min(message->find('\n'), message->size());
  const size_t at = message->rfind("a nil value (", end);
  if (at == std::string::npos) return;
  for (const char* name : {"io", "os", "debug", "dofile", "loadfile"}) {
    const size_t found = message->find(std::string(" '") + name + "')", at);
    if (found != std::string::npos && found < end) {
      message->insert(end, ": --sandbox leaves out io, os, debug, dofile and loadfile (docs/sandbox.md)");
      return;
    }
  }
}

void PrependPackagePath(lua_State* L, int package, const std::string& prefix) {
  lua_getfield(L, package, "path");
  const std::string path = prefix + (lua_tostring(L, -1) ? lua_tostring(L, -1) : "");
  lua_pop(L, 1);
  lua_pushstring(L, path.c_str());
  lua_setfield(L, package, "path");
}

void OpenGuardedLibraries(lua_State* L, bool sandbox) {
  GuardOf(L)->sandbox = sandbox;
  for (const luaL_Reg& lib : {luaL_Reg{LUA_GNAME, luaopen_base}, {LUA_MATHLIBNAME, luaopen_math}}) {
    luaL_requiref(L, lib.name, lib.func, 1);
    lua_pop(L, 1);
  }
  CloseBaseEscapes(L);
  DeclareLazyLibraries(L, sandbox);
  if (!sandbox) return;
  for (const char* name : {"dofile", "loadfile"}) {
    lua_pushnil(L);
    lua_setglobal(L, name);
  }
  lua_getglobal(L, "load");
  lua_pushcclosure(L, TextOnlyLoad, 1);
  lua_setglobal(L, "load");
}

}  // namespace essaim
