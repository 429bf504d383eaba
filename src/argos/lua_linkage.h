// What a loop-function library expects of Lua, read from its ELF file before it is
// loaded: the Lua library it was linked against and the Lua functions it calls. Code
// built with Lua 5.1 or 5.3 headers calls functions whose layout differs from the Lua
// 5.4 that runs the controllers; loading it would crash at the first call, so it is refused.
#pragma once
#include <string>
#include <vector>

namespace essaim {

struct LuaLinkage {
  std::vector<std::string> needed;     // DT_NEEDED entries
  std::vector<std::string> lua_calls;  // undefined dynamic symbols lua_*, luaL_*, luaopen_*
};

/// Reads `path`'s dynamic section; false with `error` when it is not a 64-bit ELF shared object.
bool ReadLuaLinkage(const std::string& path, LuaLinkage* out, std::string* error);

/// Why `library` cannot run against this process's Lua 5.4, or "" when it can (it calls
/// no Lua, or only Lua 5.4 functions and no other Lua library).
std::string LuaMismatch(const std::string& library, const LuaLinkage& linkage);

}  // namespace essaim
