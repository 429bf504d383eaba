// Looking into a Lua state from outside, between calls: what a live view's inspector shows.
// Reads only (raw access: no metamethod runs, nothing allocated in the state).
#pragma once
#include <string>
#include <vector>

#include "core/value.h"

struct lua_State;

namespace essaim {

struct LuaTreeLimits {
  int depth = 4;        // tables below this depth are shown as "{...}"
  int per_table = 100;  // entries shown per table; the rest counted
  int total = 3000;     // entries in the whole tree
  size_t string_chars = 200;
};

/// The script's own globals as a value tree: numbers, strings, booleans and tables, the
/// standard library, `robot` and functions left out. Null state: an empty object.
Value LuaGlobalsTree(lua_State* L, const LuaTreeLimits& limits = {});
/// One global table (e.g. "robot") as a tree, functions left out; null when not a table.
Value LuaGlobalTree(lua_State* L, const char* name, const LuaTreeLimits& limits = {});

}  // namespace essaim
