#include "lua/robot/lua_random.h"

namespace essaim {

namespace {
Rng* Self(lua_State* L) { return static_cast<Rng*>(lua_touserdata(L, lua_upvalueindex(1))); }

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
int Exponential(lua_State* L) {
  if (lua_gettop(L) != 1) return luaL_error(L, "robot.random.exponential() expects 1 argument");
  lua_pushnumber(L, Self(L)->Exponential(luaL_checknumber(L, 1)));
  return 1;
}
int Poisson(lua_State* L) {
  if (lua_gettop(L) != 1) return luaL_error(L, "robot.random.poisson() expects 1 argument");
  lua_pushinteger(L, Self(L)->Poisson(luaL_checknumber(L, 1)));
  return 1;
}
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
}  // namespace

void PushRandomTable(lua_State* L, Rng* rng) {
  static const luaL_Reg fns[] = {
      {"uniform", Uniform}, {"uniform_int", UniformInt}, {"gaussian", Gaussian}, {"exponential", Exponential},
      {"poisson", Poisson}, {"bernoulli", Bernoulli},    {nullptr, nullptr}};
  lua_createtable(L, 0, 6);
  lua_pushlightuserdata(L, rng);
  luaL_setfuncs(L, fns, 1);
}

}  // namespace essaim
