// A run's controller scripts compiled once: the first state to load a file parses it and
// dumps its bytecode here; every later state loads that bytecode instead of reading and
// parsing the file again (a third of a state's set-up cost at 100 000 robots).
//
// The bytecode only ever comes from our own lua_dump of a chunk this run parsed, kept with
// its debug information (file name, lines), so errors and tracebacks name the script as
// luaL_loadfile does. Users' bytecode never goes through here: under the sandbox the file
// is read as text only.
#pragma once
#include <mutex>
#include <string>
#include <unordered_map>

struct lua_State;

namespace essaim {

class CompiledScripts {
 public:
  /// Pushes the main chunk of `path` onto L's stack, as luaL_loadfilex would (text only
  /// when `text_only`): LUA_OK, or an error status with the message pushed ("file:line:
  /// ..." for a syntax error). Any thread: the first to ask for a file parses it while
  /// the others wait for its bytecode; a file that fails fails each state with the first
  /// parse's status and message, without being read again.
  int Load(lua_State* L, const std::string& path, bool text_only);
  /// Pushes the chunk of Lua text `text` (the host's own, e.g. coroutine.wrap's), named
  /// `chunkname`, compiled at the first call and loaded from its bytecode after that.
  /// LUA_OK, or an error status with the message pushed. Any thread; never raises.
  int LoadText(lua_State* L, const char* chunkname, const char* text, size_t size);
  /// How many files were parsed into a chunk (each once), for the tests.
  size_t Parsed() const;

 private:
  struct Chunk {
    int status = 0;     // LUA_OK, or the failed parse's status
    std::string bytes;  // the bytecode, or the failed parse's message
  };
  mutable std::mutex mutex_;
  // Keyed by path and mode: a text-only load never reuses a chunk another mode read. A
  // node never moves once made, so a chunk is read outside the lock.
  std::unordered_map<std::string, Chunk> chunks_;
  std::unordered_map<std::string, std::string> texts_;  // LoadText's, by chunk name
};

}  // namespace essaim
