// Robot handles' own methods (docs/loop-functions.md): battery, alive, kill, LEDs, the
// controller's state and its globals (ARGoS's CLuaController::GetLuaState()), and the
// handle metatable every entity handle shares. Robots are read and changed through the
// World's EntityStore only.
#include <cstring>
#include <lua.hpp>

#include "lua/loop/loop_context.h"
#include "lua/loop/loop_handles.h"

namespace essaim {

namespace {

int RobotIndex(lua_State* L) {
  EntityHandle* h = ToEntityHandle(L, 1);
  if (!h || h->ref.kind != EntityKind::FootBot) luaL_typeerror(L, 1, "robot handle");
  return static_cast<int>(h->ref.serial);
}

int Battery(lua_State* L) {
  const int i = RobotIndex(L);
  lua_pushnumber(L, LoopContextOf(L)->entities->BatteryLevel(i));
  return 1;
}

int SetBattery(lua_State* L) {
  const int i = RobotIndex(L);
  double c = luaL_checknumber(L, 2);
  if (c < 0 || c > 1) return luaL_error(L, "set_battery: charge must be in [0, 1], got %f", c);
  LoopContextOf(L)->entities->SetBatteryLevel(i, c);
  return 0;
}

int Alive(lua_State* L) {
  const int i = RobotIndex(L);
  lua_pushboolean(L, LoopContextOf(L)->entities->Robot(i).alive);
  return 1;
}

int Kill(lua_State* L) {
  const int i = RobotIndex(L);
  LoopContextOf(L)->entities->KillRobot(i);
  return 0;
}

int ControllerOk(lua_State* L) {
  const int i = RobotIndex(L);
  lua_pushboolean(L, LoopContextOf(L)->entities->Robot(i).controller_ok);
  return 1;
}

int Led(lua_State* L) {
  const int i = RobotIndex(L);
  lua_Integer k = luaL_checkinteger(L, 2);
  if (k < 1 || k > footbot::kLedCount) return luaL_error(L, "led index must be 1..13");
  const Color& c = LoopContextOf(L)->entities->Robot(i).leds[k - 1];
  lua_pushinteger(L, c.r);
  lua_pushinteger(L, c.g);
  lua_pushinteger(L, c.b);
  return 3;
}

// r:lua_global / r:set_lua_global: CLuaController::GetLuaState(). The copy crosses states
// through the tape; the controller's side runs under its own pcall, so a memory error there
// stays there.
struct CopyJob {
  LuaTape* tape;
  const char* name;
  const char* bad;
  bool ok;
};

int CollectGlobal(lua_State* C) {
  auto* job = static_cast<CopyJob*>(lua_touserdata(C, 1));
  lua_rawgeti(C, LUA_REGISTRYINDEX, LUA_RIDX_GLOBALS);
  lua_pushstring(C, job->name);
  lua_rawget(C, -2);
  job->ok = job->tape->Record(C, -1, false, &job->bad);
  return 0;
}

int StoreGlobal(lua_State* C) {
  auto* job = static_cast<CopyJob*>(lua_touserdata(C, 1));
  lua_rawgeti(C, LUA_REGISTRYINDEX, LUA_RIDX_GLOBALS);
  lua_pushstring(C, job->name);
  job->tape->Replay(C);
  lua_rawset(C, -3);
  job->ok = true;
  return 0;
}

bool RunInController(lua_State* C, lua_CFunction fn, CopyJob* job) {
  if (!lua_checkstack(C, 3)) return false;
  const int top = lua_gettop(C);
  lua_pushcfunction(C, fn);
  lua_pushlightuserdata(C, job);
  const bool ok = lua_pcall(C, 1, 0, 0) == LUA_OK;
  lua_settop(C, top);
  return ok && job->ok;
}

lua_State* ControllerState(LoopContext* ctx, int i) {
  if (!ctx->controllers || static_cast<size_t>(i) >= ctx->controllers->size()) return nullptr;
  return LuaStateOf((*ctx->controllers)[i].get());  // null: no script, or closed after its memory limit
}

int LuaGlobal(lua_State* L) {
  LoopContext* ctx = LoopContextOf(L);
  const int i = RobotIndex(L);
  const char* name = luaL_checkstring(L, 2);
  lua_State* C = ControllerState(ctx, i);
  if (!C) return lua_pushnil(L), 1;
  CopyJob job{&ctx->tape, name, nullptr, false};
  if (!RunInController(C, CollectGlobal, &job))
    return luaL_error(L, "lua_global: cannot copy '%s' from robot '%s': %s", name, ctx->model->robots[i].id.c_str(),
                      job.bad ? job.bad : "its Lua state is out of memory");
  ctx->tape.Replay(L);
  return 1;
}

int SetLuaGlobal(lua_State* L) {
  LoopContext* ctx = LoopContextOf(L);
  const int i = RobotIndex(L);
  const char* name = luaL_checkstring(L, 2);
  luaL_checkany(L, 3);
  const char* bad = nullptr;
  if (!ctx->tape.Record(L, 3, true, &bad))
    return luaL_error(L, "set_lua_global: '%s' must be plain data (numbers, strings, booleans, tables): %s", name,
                      bad ? bad : "?");
  lua_State* C = ControllerState(ctx, i);
  const RobotDef& robot = ctx->model->robots[i];
  if (!C && robot.controller >= 0 && ctx->model->controllers[robot.controller].Cpp())
    return luaL_error(L, "set_lua_global: robot '%s' runs a C++ controller (%s), which has no Lua globals",
                      robot.id.c_str(), ctx->model->controllers[robot.controller].label.c_str());
  if (!C) return luaL_error(L, "set_lua_global: robot '%s' has no running controller", robot.id.c_str());
  CopyJob job{&ctx->tape, name, nullptr, false};
  if (!RunInController(C, StoreGlobal, &job))
    return luaL_error(L, "set_lua_global: robot '%s': its Lua state is out of memory",
                      ctx->model->robots[i].id.c_str());
  return 0;
}

int HandleIndex(lua_State* L) {
  EntityHandle* h = ToEntityHandle(L, 1);
  if (!h) luaL_typeerror(L, 1, "entity handle");
  const char* k = luaL_checkstring(L, 2);
  if (!std::strcmp(k, "id")) return lua_getiuservalue(L, 1, 1), 1;  // kept after removal, for messages
  if (!std::strcmp(k, "kind")) return lua_pushstring(L, EntityKindName(h->ref.kind)), 1;
  if (!std::strcmp(k, "index")) {
    if (h->ref.kind == EntityKind::FootBot)
      lua_pushinteger(L, static_cast<lua_Integer>(h->ref.serial) + 1);
    else
      lua_pushnil(L);
    return 1;
  }
  lua_getmetatable(L, 1);
  lua_pushvalue(L, 2);
  lua_rawget(L, -2);
  return 1;
}

}  // namespace

void OpenRobotApi(lua_State* L) {
  static const luaL_Reg handle_methods[] = {{"battery", Battery},
                                            {"lua_global", LuaGlobal},
                                            {"set_lua_global", SetLuaGlobal},
                                            {"set_battery", SetBattery},
                                            {"alive", Alive},
                                            {"kill", Kill},
                                            {"led", Led},
                                            {"controller_ok", ControllerOk},
                                            {nullptr, nullptr}};
  lua_newtable(L);  // the handle metatable
  luaL_setfuncs(L, handle_methods, 0);
  lua_pushcfunction(L, HandleIndex);
  lua_setfield(L, -2, "__index");
  LoopContextOf(L)->handle_meta = lua_topointer(L, -1);  // kept alive by the registry
  lua_rawsetp(L, LUA_REGISTRYINDEX, &kHandleMetaKey);
}

}  // namespace essaim
