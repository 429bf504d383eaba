// The guarded allocator every Lua state runs on (lua/host/lua_guard.h, over the small-block
// pool of lua/host/small_block_pool.h): its accounting is exact on every path it takes.
#include <gtest/gtest.h>

#include <lua.hpp>

#include "lua/host/lua_guard.h"

namespace essaim {
namespace {

TEST(GuardedAllocator, CountsExactlyTheBytesLuaHolds) {
  // Lua counts its own bytes (collectgarbage("count")); the guard's count must match it
  // whatever path each call took: new and freed small blocks, growth within a class and
  // across classes, between the pool and malloc (arrays and strings over 256 bytes), and
  // large to large. The peak is at least every value seen, allocations only grow.
  LuaGuard g;
  LuaOptions unlimited;
  unlimited.memory_limit = 0;
  unlimited.instruction_limit = unlimited.setup_instruction_limit = 0;
  unlimited.wall_seconds = 0;
  lua_State* L = NewGuardedState(&g, unlimited);
  ASSERT_NE(L, nullptr);
  luaL_openlibs(L);
  auto lua_bytes = [L] { return static_cast<size_t>(lua_gc(L, LUA_GCCOUNT)) * 1024 + lua_gc(L, LUA_GCCOUNTB); };
  EXPECT_EQ(g.bytes, lua_bytes());
  const char* script = R"(
    local keep = {}
    for round = 1, 30 do
      local t = {}
      for i = 1, round * 40 do t[i] = i end                  -- array grows: pool, then malloc
      local h = {}
      for i = 1, round * 5 do h["k" .. i] = {i} end          -- hash part and small tables
      local s = string.rep("x", round * 20)                  -- strings from 20 to 600 bytes
      keep[round % 7 + 1] = {t, h, s}
      if round % 10 == 0 then collectgarbage() end
    end
    return #keep
  )";
  size_t last_allocations = g.allocations;
  for (int run = 0; run < 3; ++run) {
    ASSERT_EQ(luaL_dostring(L, script), LUA_OK) << lua_tostring(L, -1);
    lua_settop(L, 0);
    EXPECT_EQ(g.bytes, lua_bytes()) << "run " << run;
    EXPECT_GE(g.peak, g.bytes);
    EXPECT_GT(g.allocations, last_allocations);
    last_allocations = g.allocations;
  }
  lua_gc(L, LUA_GCCOLLECT);
  EXPECT_EQ(g.bytes, lua_bytes());
  EXPECT_LT(g.bytes, g.peak);  // the collection gave blocks back
  CloseGuardedState(&g);
  EXPECT_EQ(g.bytes, 0u);  // lua_close freed everything through the allocator
}

}  // namespace
}  // namespace essaim
