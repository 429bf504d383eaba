// The text of a controller's or loop functions' log line, as ARGoS writes it (print's and
// io.write's: stdout_lines.h).
#pragma once

#include <string>

struct lua_State;

namespace essaim {

/// ARGoS's log() and logerr(): the arguments one after the other with no separator, numbers
/// as a C++ stream prints them (6 significant digits: 0.333333, 1e+08, 3 for 3.0), booleans
/// 1/0, strings as they are, any other value by its type name (nil, table...).
void AppendArgosLogText(lua_State* L, std::string* out);

/// Ends the entry that starts at `begin` of a log buffer ("<stream><text>\n" per line): a
/// newline inside the text starts a line of the same stream, so no character of it is lost.
void EndLogEntry(std::string* log, size_t begin);

}  // namespace essaim
