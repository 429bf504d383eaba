// What a script writes to the process's stdout, made lines of its log: print, and the io
// library's writes while they go to io.stdout. Every other write is Lua's own.
#pragma once
#include <cstddef>
#include <string>

struct lua_State;

namespace essaim {

/// The log buffer ("<stream><text>\n" per entry) and the line not ended yet: each whole
/// line becomes an 'O' entry; an open line waits for more text, as on a real stdout
/// (io.write("a") then print("b") make the line "ab"), until EndWrittenLine.
struct WrittenLines {
  std::string* log = nullptr;
  std::string open;
};
void AppendWritten(WrittenLines* lines, const char* text, size_t len);
/// Ends a line left open; nothing if none is. Each call into a script ends with it, so
/// that one robot's text never runs into another's line.
void EndWrittenLine(WrittenLines* lines);

/// For a guarded state: the global print (Lua's text) writes to `lines`, and so do, once
/// the script uses io, io.write while the default output is io.stdout and io.stdout:write.
/// `lines` must outlive the state.
void RouteStdout(lua_State* L, WrittenLines* lines);
/// The log buffer RouteStdout gave `L`'s lines (null: none), where log() writes too.
std::string* RoutedLog(lua_State* L);

}  // namespace essaim
