// experiment.add_entity(kind, spec): a box, cylinder or light from a Lua table, checked as
// the .argos loader checks the file, then added through the World's EntityStore (the same
// physics and scene calls World creation makes).
//
// Lua errors longjmp: no C++ object with a destructor lives across a Lua API call that can
// raise. Specs are parsed into the loop context's scratch defs for that reason.
#include <cmath>
#include <cstring>
#include <lua.hpp>

#include "core/color.h"
#include "lua/loop/loop_context.h"
#include "lua/loop/loop_handles.h"

namespace essaim {

namespace {

// Raw field access on the spec (argument 2): its metamethods never run.
int Field(lua_State* L, const char* name) {
  lua_pushstring(L, name);
  return lua_rawget(L, 2);
}

double Number(lua_State* L, const char* name, double def, bool required) {
  const int t = Field(L, name);
  double v = def;
  if (t == LUA_TNIL && required) luaL_error(L, "add_entity: spec needs '%s'", name);
  if (t != LUA_TNIL) {
    if (!lua_isnumber(L, -1)) luaL_error(L, "add_entity: '%s' must be a number", name);
    v = lua_tonumber(L, -1);
    if (!std::isfinite(v)) luaL_error(L, "add_entity: '%s' must be finite", name);
  }
  lua_pop(L, 1);
  return v;
}

/// {x, y[, z]} at the top of the stack (popped).
Vec3 Triple(lua_State* L, const char* name, int min_count) {
  if (!lua_istable(L, -1)) luaL_error(L, "add_entity: '%s' must be a table {x, y, z}", name);
  Vec3 v = Vec3::Zero();
  for (int k = 0; k < 3; ++k) {
    const int t = lua_rawgeti(L, -1, k + 1);
    if (t == LUA_TNIL && k >= min_count) {
      lua_pop(L, 1);
      continue;
    }
    if (!lua_isnumber(L, -1) || !std::isfinite(lua_tonumber(L, -1)))
      luaL_error(L, "add_entity: '%s' must be {x, y, z} with finite numbers", name);
    v[k] = lua_tonumber(L, -1);
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  return v;
}

Color ColorField(lua_State* L, int idx, const char* name) {
  if (lua_type(L, idx) == LUA_TSTRING) {
    auto c = ParseColor(lua_tostring(L, idx));
    if (!c) luaL_error(L, "add_entity: bad colour '%s' in '%s'", lua_tostring(L, idx), name);
    return c ? *c : Color();
  }
  if (lua_istable(L, idx)) {
    Vec3 v = (lua_pushvalue(L, idx), Triple(L, name, 3));
    if (v.minCoeff() < 0 || v.maxCoeff() > 255) luaL_error(L, "add_entity: '%s' components must be in 0-255", name);
    return Color{static_cast<unsigned char>(v.x()), static_cast<unsigned char>(v.y()),
                 static_cast<unsigned char>(v.z()), 255};
  }
  luaL_error(L, "add_entity: '%s' must be a colour name or {r, g, b}", name);
  return Color();
}

void CheckMedium(lua_State* L, const Model& model, const std::string& medium) {
  for (const LedMediumDef& m : model.led_media)
    if (m.id == medium) return;
  luaL_error(L, "add_entity: medium '%s' is not declared in <media> (<led id=\"%s\"/>)", medium.c_str(),
             medium.c_str());
}

void SetString(lua_State* L, const char* name, std::string* out, bool required) {
  const int t = Field(L, name);
  if (t == LUA_TNIL && required) luaL_error(L, "add_entity: spec needs '%s'", name);
  if (t != LUA_TNIL && t != LUA_TSTRING) luaL_error(L, "add_entity: '%s' must be a string", name);
  if (t == LUA_TSTRING) *out = lua_tostring(L, -1);
  lua_pop(L, 1);
}

/// leds[k] at the top of the stack (left there).
LedDef ParseLed(lua_State* L, lua_Integer k) {
  LedDef led;
  lua_pushliteral(L, "offset");
  if (lua_rawget(L, -2) == LUA_TNIL)
    lua_pop(L, 1);
  else
    led.offset = Triple(L, "offset", 3);
  lua_pushliteral(L, "anchor");
  if (lua_rawget(L, -2) != LUA_TNIL && (!lua_isstring(L, -1) || std::strcmp(lua_tostring(L, -1), "origin")))
    luaL_error(L, "add_entity: leds[%d].anchor: boxes and cylinders have one anchor, \"origin\"", static_cast<int>(k));
  lua_pop(L, 1);
  lua_pushliteral(L, "color");
  if (lua_rawget(L, -2) != LUA_TNIL) led.color = ColorField(L, -1, "color");
  lua_pop(L, 1);
  return led;
}

void ParseLeds(lua_State* L, const Model& model, ObstacleDef* o) {
  if (Field(L, "leds") == LUA_TNIL) return lua_pop(L, 1);
  if (!lua_istable(L, -1)) luaL_error(L, "add_entity: 'leds' must be an array of {offset = {x, y, z}, color = ...}");
  const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, -1));
  for (lua_Integer k = 1; k <= n; ++k) {
    if (lua_rawgeti(L, -1, k) != LUA_TTABLE) luaL_error(L, "add_entity: leds[%d] must be a table", static_cast<int>(k));
    o->leds.push_back(ParseLed(L, k));
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  if (!o->leds.empty()) {
    SetString(L, "medium", &o->led_medium, true);
    CheckMedium(L, model, o->led_medium);
  }
}

/// Raises "add_entity: " + `problem` at the script's line unless it is "". The message is
/// on Lua's stack before `problem` goes: lua_error's longjmp skips C++ destructors.
void RaiseIf(lua_State* L, std::string&& problem) {
  if (problem.empty()) return;
  luaL_where(L, 1);
  lua_pushfstring(L, "add_entity: %s", problem.c_str());
  lua_concat(L, 2);
  std::string().swap(problem);
  lua_error(L);
}

void ParseLight(lua_State* L, LoopContext* ctx, int line) {
  LightDef& l = ctx->light_spec;
  l = LightDef();
  l.loc = {ctx->script, line, "add_entity"};
  l.position = (Field(L, "position") == LUA_TNIL ? (luaL_error(L, "add_entity: spec needs 'position'"), Vec3())
                                                 : Triple(L, "position", 2));
  if (Field(L, "color") == LUA_TNIL) luaL_error(L, "add_entity: spec needs 'color'");
  l.color = ColorField(L, -1, "color");
  lua_pop(L, 1);
  l.intensity = Number(L, "intensity", 1.0, false);
  if (l.intensity < 0) luaL_error(L, "add_entity: 'intensity' must be >= 0");
  SetString(L, "medium", &l.medium, true);
  CheckMedium(L, *ctx->model, l.medium);
}

void ParseShape(lua_State* L, EntityKind kind, ObstacleDef* o) {
  if (kind == EntityKind::Box) {
    if (Field(L, "size") == LUA_TNIL) luaL_error(L, "add_entity: a box spec needs 'size' = {x, y, z}");
    const Vec3 s = Triple(L, "size", 3);
    if (s.minCoeff() <= 0) luaL_error(L, "add_entity: size components must be > 0");
    o->size_x = s.x(), o->size_y = s.y(), o->height = s.z();
  } else {
    o->radius = Number(L, "radius", 0, true);
    o->height = Number(L, "height", 0, true);
    if (o->radius <= 0 || o->height <= 0) luaL_error(L, "add_entity: radius and height must be > 0");
  }
}

void ParseObstacle(lua_State* L, LoopContext* ctx, EntityKind kind, int line) {
  ObstacleDef& o = ctx->obstacle_spec;
  o = ObstacleDef();
  o.kind = kind == EntityKind::Box ? ShapeKind::Box : ShapeKind::Cylinder;
  o.loc = {ctx->script, line, "add_entity"};
  if (Field(L, "position") == LUA_TNIL) luaL_error(L, "add_entity: spec needs 'position'");
  const Vec3 p = Triple(L, "position", 2);
  o.pose = {p.x(), p.y(), DegToRad(Number(L, "orientation", 0, false))};
  o.z = p.z();
  ParseShape(L, kind, &o);
  const int t = Field(L, "movable");
  if (t != LUA_TNIL && t != LUA_TBOOLEAN) luaL_error(L, "add_entity: 'movable' must be a boolean");
  o.movable = lua_toboolean(L, -1);
  lua_pop(L, 1);
  if (o.movable) {
    o.mass = Number(L, "mass", 0, true);
    if (o.mass <= 0) luaL_error(L, "add_entity: mass must be > 0 for a movable object");
  }
  ParseLeds(L, *ctx->model, &o);
  RaiseIf(L, ctx->entities->ObstacleProblemNow(o));
}

// A foot-bot as <foot-bot> declares one: the controller by its <lua_controller id> (the
// store binds it), the rab_* attributes; battery and dynamics as the XML's defaults.
void ParseFootBot(lua_State* L, LoopContext* ctx, int line) {
  RobotDef& r = ctx->robot_spec;
  r = RobotDef();
  r.loc = {ctx->script, line, "add_entity"};
  if (Field(L, "position") == LUA_TNIL) luaL_error(L, "add_entity: spec needs 'position'");
  const Vec3 p = Triple(L, "position", 2);
  r.pose = {p.x(), p.y(), DegToRad(Number(L, "orientation", 0, false))};
  r.z = p.z();
  SetString(L, "controller", &r.controller_id, true);
  r.rab_range = Number(L, "rab_range", 3.0, false);
  if (r.rab_range < 0) luaL_error(L, "add_entity: 'rab_range' must be >= 0");
  const double data_size = Number(L, "rab_data_size", 10, false);
  if (data_size < 0 || data_size > 65536 || data_size != std::floor(data_size))
    luaL_error(L, "add_entity: 'rab_data_size' must be a whole number of bytes, 0 to 65536");
  r.rab_data_size = static_cast<int>(data_size);
}

/// The spec's id, or one made of the kind and a counter, skipping any taken.
void AssignId(lua_State* L, const EntityStore& store, const char* kind_name, std::string* id) {
  SetString(L, "id", id, false);
  if (id->empty()) {
    for (int n = static_cast<int>(store.All().size());; ++n) {
      *id = std::string(kind_name) + "_" + std::to_string(n);
      if (!store.HasId(*id)) break;
    }
  } else if (store.HasId(*id)) {
    luaL_error(L, "add_entity: id '%s' is already used", id->c_str());
  }
}

// The robot's controller runs its script and init() before this returns, as in ARGoS.
int AddFootBot(lua_State* L, LoopContext* ctx, int line) {
  ParseFootBot(L, ctx, line);
  AssignId(L, *ctx->entities, "fb", &ctx->robot_spec.id);
  EntityRef e;
  if (!ctx->entities->AddRobot(ctx->robot_spec, &e, &ctx->add_error)) RaiseIf(L, std::move(ctx->add_error));
  PushEntityHandle(L, e, ctx->entities->IdOf(e).c_str());
  lua_rawgetp(L, LUA_REGISTRYINDEX, &kRobotListKey);  // experiment.robots[index + 1] = the handle
  lua_pushvalue(L, -2);
  lua_rawseti(L, -2, static_cast<lua_Integer>(e.serial) + 1);
  lua_pop(L, 1);
  return 1;
}
}  // namespace

int AddEntity(lua_State* L) {
  LoopContext* ctx = LoopContextOf(L);
  EntityKind kind;
  const char* kind_name = luaL_checkstring(L, 1);
  if (!ParseEntityKind(kind_name, &kind))
    return luaL_error(L, "add_entity: unknown kind '%s' (foot-bot, box, cylinder or light)", kind_name);
  luaL_checktype(L, 2, LUA_TTABLE);
  lua_settop(L, 2);
  lua_Debug ar;
  const int line = lua_getstack(L, 1, &ar) && lua_getinfo(L, "l", &ar) ? ar.currentline : 0;
  if (kind == EntityKind::FootBot) return AddFootBot(L, ctx, line);
  const bool light = kind == EntityKind::Light;
  if (light)
    ParseLight(L, ctx, line);
  else
    ParseObstacle(L, ctx, kind, line);
  RaiseIf(L, ctx->entities->RoomProblem(false));
  AssignId(L, *ctx->entities, kind_name, light ? &ctx->light_spec.id : &ctx->obstacle_spec.id);
  const EntityRef e = light ? ctx->entities->AddLight(ctx->light_spec) : ctx->entities->AddObstacle(ctx->obstacle_spec);
  PushEntityHandle(L, e, ctx->entities->IdOf(e).c_str());
  return 1;
}

}  // namespace essaim
