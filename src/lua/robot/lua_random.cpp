#include "lua/robot/lua_random.h"

#include "lua/robot/lua_devices.h"

namespace essaim {

namespace {
// Where a function finds its stream: a controller's robot (light C functions, nothing
// allocated per state) or the closure's upvalue (the loop functions' own).
Rng* UpvalueRng(lua_State* L) { return static_cast<Rng*>(lua_touserdata(L, lua_upvalueindex(1))); }
Rng* RobotRng(lua_State* L) { return &RobotOf(L)->controller_rng; }
using RngOf = Rng* (*)(lua_State*);

template <RngOf Self>
int Uniform(lua_State* L) {
  Rng* r = Self(L);
  switch (lua_gettop(L)) {
    case 0:
      lua_pushnumber(L, r->Uniform01());
      return 1;
    case 1:
      lua_pushnumber(L, r->Uniform(0, luaL_checknumber(L, 1)));
      return 1;
    case 2:
      lua_pushnumber(L, r->Uniform(luaL_checknumber(L, 1), luaL_checknumber(L, 2)));
      return 1;
    default:
      return luaL_error(L, "robot.random.uniform() expects 0, 1 or 2 arguments");
  }
}
// Integers as Lua integers (ARGoS pushes floats; 5.4 would print them "3.0").
template <RngOf Self>
int UniformInt(lua_State* L) {
  Rng* r = Self(L);
  switch (lua_gettop(L)) {
    case 1:
      lua_pushinteger(L, r->UniformInt(0, luaL_checknumber(L, 1)));
      return 1;
    case 2:
      lua_pushinteger(L, r->UniformInt(luaL_checknumber(L, 1), luaL_checknumber(L, 2)));
      return 1;
    default:
      return luaL_error(L, "robot.random.uniform_int() expects 1 or 2 arguments");
  }
}
template <RngOf Self>
int Gaussian(lua_State* L) {
  Rng* r = Self(L);
  switch (lua_gettop(L)) {
    case 1:
      lua_pushnumber(L, r->Gaussian(luaL_checknumber(L, 1)));
      return 1;
    case 2:
      lua_pushnumber(L, r->Gaussian(luaL_checknumber(L, 1), luaL_checknumber(L, 2)));
      return 1;
    default:
      return luaL_error(L, "robot.random.gaussian() expects 1 or 2 arguments (std_dev, mean)");
  }
}
template <RngOf Self>
int Exponential(lua_State* L) {
  if (lua_gettop(L) != 1) return luaL_error(L, "robot.random.exponential() expects 1 argument");
  lua_pushnumber(L, Self(L)->Exponential(luaL_checknumber(L, 1)));
  return 1;
}
template <RngOf Self>
int Poisson(lua_State* L) {
  if (lua_gettop(L) != 1) return luaL_error(L, "robot.random.poisson() expects 1 argument");
  lua_pushinteger(L, Self(L)->Poisson(luaL_checknumber(L, 1)));
  return 1;
}
template <RngOf Self>
int Bernoulli(lua_State* L) {
  Rng* r = Self(L);
  switch (lua_gettop(L)) {
    case 0:
      lua_pushboolean(L, r->Bernoulli());
      return 1;
    case 1:
      lua_pushboolean(L, r->Bernoulli(luaL_checknumber(L, 1)));
      return 1;
    default:
      return luaL_error(L, "robot.random.bernoulli() expects 0 or 1 argument");
  }
}

template <RngOf Self>
void PushFunctions(lua_State* L, int upvalues) {
  static const luaL_Reg fns[] = {{"uniform", Uniform<Self>},
                                 {"uniform_int", UniformInt<Self>},
                                 {"gaussian", Gaussian<Self>},
                                 {"exponential", Exponential<Self>},
                                 {"poisson", Poisson<Self>},
                                 {"bernoulli", Bernoulli<Self>},
                                 {nullptr, nullptr}};
  luaL_setfuncs(L, fns, upvalues);
}
}  // namespace

void PushRandomTable(lua_State* L, Rng* rng) {
  lua_createtable(L, 0, 6);
  lua_pushlightuserdata(L, rng);
  PushFunctions<UpvalueRng>(L, 1);
}

void PushRobotRandomTable(lua_State* L) {
  lua_createtable(L, 0, 6);
  PushFunctions<RobotRng>(L, 0);
}

}  // namespace essaim
