// Where every lua_State is made: the guarded ones (controllers, loop functions) and the
// stock one the bare floor times; and math.random's seeding, which Lua 5.4 takes from the
// clock unless told otherwise.
#pragma once
#include <cstdint>
#include <string>

#include "lua/host/lua_guard.h"

struct lua_State;

namespace essaim {

/// A state on Lua's own allocator (malloc), with no guard: "bare Lua 5.4".
lua_State* NewStockState();

/// math.randomseed(seed, index), seed as a non-negative Lua integer: reproducible per
/// experiment seed and robot.
void SeedMathRandom(lua_State* L, uint64_t seed, int64_t index);

/// `require` finds modules next to the script first: its folder's ?.lua and ?/init.lua go
/// before package.path.
void PrependScriptFolder(lua_State* L, const std::string& script);

}  // namespace essaim
