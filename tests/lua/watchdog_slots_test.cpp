// The watchdog looks at one slot per calling thread, never at every state
// (lua/host/watchdog.h): a guarded call puts its state in the slot and takes it out.
#include <gtest/gtest.h>

#include <lua.hpp>
#include <memory>
#include <thread>
#include <vector>

#include "lua/host/lua_guard.h"
#include "lua/host/watchdog.h"

namespace essaim {
namespace {

// One guarded state on `watchdog`, closed with its guard.
struct Guarded {
  LuaGuard guard;
  lua_State* L = nullptr;
  Guarded(Watchdog* watchdog, double wall_seconds = 60) {
    LuaOptions o;
    o.watchdog = watchdog;
    o.instruction_limit = o.setup_instruction_limit = 0;
    o.wall_seconds = wall_seconds;
    L = NewGuardedState(&guard, o);
    luaL_openlibs(L);
  }
  ~Guarded() { CloseGuardedState(&guard); }
  /// Runs `code` as one guarded call; "" or what stopped it (EndGuardedCall's reason or
  /// Lua's error).
  std::string Run(const char* code) {
    if (luaL_loadstring(L, code) != LUA_OK) return lua_tostring(L, -1);
    BeginGuardedCall(&guard, CallKind::Step);
    const int status = lua_pcall(L, 0, 0, 0);
    std::string stopped = EndGuardedCall(&guard, status);
    if (stopped.empty() && status != LUA_OK) stopped = lua_tostring(L, -1);
    lua_settop(L, 0);
    return stopped;
  }
};

TEST(WatchdogSlots, OneSlotPerThreadWhateverTheNumberOfStates) {
  Watchdog watchdog;
  std::vector<std::unique_ptr<Guarded>> states;
  for (int i = 0; i < 200; ++i) states.push_back(std::make_unique<Guarded>(&watchdog));
  EXPECT_EQ(watchdog.Slots(), 0u);  // making states registers nothing
  for (auto& s : states) EXPECT_EQ(s->Run("local x = 1"), "");
  EXPECT_EQ(watchdog.Slots(), 1u);
  std::thread other([&] {
    for (size_t i = 0; i < 50; ++i) EXPECT_EQ(states[i]->Run("local x = 2"), "");
  });
  other.join();
  EXPECT_EQ(watchdog.Slots(), 2u);
  for (auto& s : states) EXPECT_EQ(s->Run("local x = 3"), "");
  EXPECT_EQ(watchdog.Slots(), 2u);
}

// The slot holds the state during its call only; a call made inside another puts the outer
// state back when it ends.
int SlotHolds(lua_State* L) {
  auto* watchdog = static_cast<Watchdog*>(lua_touserdata(L, lua_upvalueindex(1)));
  lua_pushlightuserdata(L, watchdog->ThisThreadSlot()->guard.load());
  return 1;
}

TEST(WatchdogSlots, TheSlotNamesTheRunningStateAndNestedCallsRestoreIt) {
  Watchdog watchdog;
  Guarded outer(&watchdog), inner(&watchdog);
  for (Guarded* g : {&outer, &inner}) {
    lua_pushlightuserdata(g->L, &watchdog);
    lua_pushcclosure(g->L, SlotHolds, 1);
    lua_setglobal(g->L, "slot");
  }
  lua_pushlightuserdata(outer.L, &outer.guard);
  lua_setglobal(outer.L, "me");
  lua_pushlightuserdata(inner.L, &inner.guard);
  lua_setglobal(inner.L, "me");
  // From outer's call, a C function runs inner's call, then outer checks the slot again.
  lua_pushlightuserdata(outer.L, &inner);
  lua_pushcclosure(
      outer.L,
      [](lua_State* L) {
        auto* in = static_cast<Guarded*>(lua_touserdata(L, lua_upvalueindex(1)));
        lua_pushstring(L, in->Run("assert(slot() == me, 'inner slot')").c_str());
        return 1;
      },
      1);
  lua_setglobal(outer.L, "run_inner");
  EXPECT_EQ(outer.Run("assert(slot() == me, 'outer slot'); assert(run_inner() == ''); "
                      "assert(slot() == me, 'outer slot after inner')"),
            "");
  EXPECT_EQ(watchdog.ThisThreadSlot()->guard.load(), nullptr);
}

TEST(WatchdogSlots, ALongCallOnAnotherThreadIsStoppedByTheWallClock) {
  Watchdog watchdog;
  Guarded idle(&watchdog), runaway(&watchdog, 0.3);
  std::string stopped;
  std::thread worker([&] { stopped = runaway.Run("while true do end"); });
  EXPECT_EQ(idle.Run("local x = 1"), "");  // the main thread's slot comes and goes meanwhile
  worker.join();
  EXPECT_NE(stopped.find("wall-clock limit exceeded (0.3 s per call)"), std::string::npos) << stopped;
}

}  // namespace
}  // namespace essaim
