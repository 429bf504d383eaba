// The lines of a Lua file that hold code, for moving a breakpoint to the next such line as
// debuggers do. Lua's API gives the active lines of a function it can reach (lua_getinfo
// "L"), but a chunk's nested functions are reachable only once they run; the file's
// compiled form (lua_dump) holds them all, so it is read instead.
#pragma once
#include <set>
#include <string>

namespace essaim {

/// Every line of `path` that holds an instruction, in any function of the file. False
/// with `error` (Lua's message) when the file does not load.
bool ActiveLinesOfFile(const std::string& path, std::set<int>* lines, std::string* error);

/// The same for Lua source text (`chunkname` names it in errors).
bool ActiveLinesOfText(const std::string& text, const std::string& chunkname, std::set<int>* lines, std::string* error);

/// The first line >= `line` that holds code; 0 when none does.
int NextActiveLine(const std::set<int>& lines, int line);

}  // namespace essaim
