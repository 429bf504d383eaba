// print and the io library's writes to the process's stdout, as log lines (robot order under
// threads, --log-prefix, --log-dir, the live view, Python logging). Lua's io library stays
// whole: io.output, io.close, io.lines... are its own, and each state has its own default
// output (in its registry). Only the write that reaches C's stdout is replaced, at the one
// place it happens: io.write while the default output is io.stdout, and the file method
// write on io.stdout (io.stdout:write, io.output():write).
#include "lua/host/stdout_lines.h"

#include <cstdio>
#include <cstring>
#include <lua.hpp>

#include "lua/host/guard_hook.h"

namespace essaim {

namespace {
void EmitLine(WrittenLines* lines) {
  *lines->log += 'O';
  *lines->log += lines->open;
  *lines->log += '\n';
  lines->open.clear();  // keeps its capacity: no allocation per line once warm
}
}  // namespace

void AppendWritten(WrittenLines* lines, const char* text, size_t len) {
  for (const char* end = text + len; text != end;) {
    const auto rest = static_cast<size_t>(end - text);
    const auto* newline = static_cast<const char*>(std::memchr(text, '\n', rest));
    if (!newline) {
      lines->open.append(text, rest);
      return;
    }
    lines->open.append(text, static_cast<size_t>(newline - text));
    EmitLine(lines);  // an empty line too
    text = newline + 1;
  }
}

void EndWrittenLine(WrittenLines* lines) {
  if (!lines->open.empty()) EmitLine(lines);
}

namespace {
// The "_IO_output" of Lua 5.4's liolib: where it keeps a state's default output.
const char kDefaultOutput[] = "_IO_output";

// The value at `index` is the open io.stdout (a file handle on C's stdout).
bool IsOpenStdout(lua_State* L, int index) {
  const auto* stream = static_cast<luaL_Stream*>(luaL_testudata(L, index, LUA_FILEHANDLE));
  return stream && stream->closef && stream->f == stdout;
}

// Arguments first..last as liolib's g_write writes them: integers with LUA_INTEGER_FMT,
// floats with LUA_NUMBER_FMT (io.write(1.0) writes "1", not tostring's "1.0"), strings as
// they are, anything else the error Lua raises.
void WriteArguments(lua_State* L, int first, int last, WrittenLines* lines) {
  for (int i = first; i <= last; ++i) {
    if (lua_type(L, i) == LUA_TNUMBER) {
      char text[64];
      const int len = lua_isinteger(L, i)
                          ? std::snprintf(text, sizeof text, LUA_INTEGER_FMT, (LUAI_UACINT)lua_tointeger(L, i))
                          : std::snprintf(text, sizeof text, LUA_NUMBER_FMT, (LUAI_UACNUMBER)lua_tonumber(L, i));
      AppendWritten(lines, text, static_cast<size_t>(len));
    } else {
      size_t len = 0;
      const char* text = luaL_checklstring(L, i, &len);
      AppendWritten(lines, text, len);
    }
  }
}

// io.write(...): to the log while the default output is io.stdout, else Lua's own. Returns
// the default output, as Lua's.
int RoutedIoWrite(lua_State* L) {
  LuaGuard* g = GuardOf(L);
  const int n = lua_gettop(L);
  lua_getfield(L, LUA_REGISTRYINDEX, kDefaultOutput);
  if (!IsOpenStdout(L, -1)) {
    lua_settop(L, n);
    return g->original_io_write(L);
  }
  WriteArguments(L, 1, n, g->stdout_lines);
  return 1;
}

// file:write(...): to the log when the file is io.stdout, else Lua's own. Returns the file.
int RoutedFileWrite(lua_State* L) {
  LuaGuard* g = GuardOf(L);
  if (!IsOpenStdout(L, 1)) return g->original_file_write(L);
  WriteArguments(L, 2, lua_gettop(L), g->stdout_lines);
  lua_pushvalue(L, 1);
  return 1;
}

// print as Lua 5.4's (luaL_tolstring of each argument, tabs, a newline), into the lines.
int RoutedPrint(lua_State* L) {
  WrittenLines* lines = GuardOf(L)->stdout_lines;
  const int n = lua_gettop(L);
  for (int i = 1; i <= n; ++i) {
    if (i > 1) AppendWritten(lines, "\t", 1);
    size_t len = 0;
    const char* text = luaL_tolstring(L, i, &len);
    AppendWritten(lines, text, len);
    lua_pop(L, 1);
  }
  AppendWritten(lines, "\n", 1);
  return 0;
}

// Replaces table[field] (the table at `t`) by `fn`, returning the original.
lua_CFunction Replace(lua_State* L, int t, const char* field, lua_CFunction fn) {
  lua_getfield(L, t, field);
  const lua_CFunction original = lua_tocfunction(L, -1);
  lua_pop(L, 1);
  lua_pushcfunction(L, fn);
  lua_setfield(L, t, field);
  return original;
}
}  // namespace

void RouteStdout(lua_State* L, WrittenLines* lines) {
  GuardOf(L)->stdout_lines = lines;
  lua_pushcfunction(L, RoutedPrint);
  lua_setglobal(L, "print");
}

std::string* RoutedLog(lua_State* L) {
  WrittenLines* lines = GuardOf(L)->stdout_lines;
  return lines ? lines->log : nullptr;
}

void RouteIoWrites(lua_State* L) {
  LuaGuard* g = GuardOf(L);
  if (!g->stdout_lines) return;
  g->original_io_write = Replace(L, lua_gettop(L), "write", RoutedIoWrite);
  // The methods every file handle shares: the __index of liolib's metatable.
  luaL_getmetatable(L, LUA_FILEHANDLE);
  if (lua_getfield(L, -1, "__index") == LUA_TTABLE)
    g->original_file_write = Replace(L, lua_gettop(L), "write", RoutedFileWrite);
  lua_pop(L, 2);
}

}  // namespace essaim
