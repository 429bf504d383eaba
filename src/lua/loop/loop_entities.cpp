// Loop functions' reach over every entity (docs/loop-functions.md, ARGoS's CSpace):
// experiment.entities / remove_entity, and the handle methods shared by foot-bots, boxes,
// cylinders and lights (pose, LEDs, light intensity and colour). Every read and change goes
// through the World's EntityStore, which raises the "scene changed" flag the step turns
// into a media refresh; they only happen in loop-function stages.
//
// Lua errors longjmp: no C++ object with a destructor lives across a Lua API call that can
// raise.
#include <cmath>
#include <cstring>
#include <lua.hpp>

#include "core/color.h"
#include "lua/loop/loop_context.h"
#include "lua/loop/loop_handles.h"

namespace essaim {

const char kHandleMetaKey = 0, kHandleCacheKey = 0, kRobotListKey = 0;

namespace {
lua_Integer CacheKey(const EntityRef& e) {
  return (static_cast<lua_Integer>(e.kind) << 32) | static_cast<lua_Integer>(e.serial);
}
}  // namespace

void PushEntityHandle(lua_State* L, const EntityRef& e, const char* id) {
  lua_rawgetp(L, LUA_REGISTRYINDEX, &kHandleCacheKey);
  if (lua_rawgeti(L, -1, CacheKey(e)) == LUA_TNIL) {
    lua_pop(L, 1);
    auto* h = static_cast<EntityHandle*>(lua_newuserdatauv(L, sizeof(EntityHandle), 1));
    h->ref = e;
    lua_pushstring(L, id);
    lua_setiuservalue(L, -2, 1);
    lua_rawgetp(L, LUA_REGISTRYINDEX, &kHandleMetaKey);
    lua_setmetatable(L, -2);
    lua_pushvalue(L, -1);
    lua_rawseti(L, -3, CacheKey(e));
  }
  lua_remove(L, -2);
}

EntityHandle* ToEntityHandle(lua_State* L, int idx) {
  void* p = lua_touserdata(L, idx);
  if (!p || !lua_getmetatable(L, idx)) return nullptr;
  // The metatable by address, not through the registry: every handle method starts here.
  const bool ok = lua_topointer(L, -1) == LoopContextOf(L)->handle_meta;
  lua_pop(L, 1);
  return ok ? static_cast<EntityHandle*>(p) : nullptr;
}

LoopContext* LoopContextOf(lua_State* L) {
  // Set by Load in the state's extra space (coroutines inherit a copy): a registry lookup
  // here cost ~200 instructions per handle call.
  return *static_cast<LoopContext**>(lua_getextraspace(L));
}

namespace {

/// The live entity behind argument 1: its ref and current index; raises otherwise.
int Resolve(lua_State* L, const char* what, EntityStore** store, EntityRef* ref) {
  EntityHandle* h = ToEntityHandle(L, 1);
  if (!h) return luaL_error(L, "%s: entity handle expected (call it as handle:%s(...))", what, what);
  *store = LoopContextOf(L)->entities;
  *ref = h->ref;
  const int index = (*store)->IndexOf(h->ref);
  if (index < 0) {
    lua_getiuservalue(L, 1, 1);
    return luaL_error(L, "%s: %s '%s' was removed by experiment.remove_entity", what, EntityKindName(h->ref.kind),
                      lua_tostring(L, -1));
  }
  return index;
}

int WrongKind(lua_State* L, const char* what, const EntityRef& e, const char* expected) {
  lua_getiuservalue(L, 1, 1);
  return luaL_error(L, "%s: '%s' is a %s, not %s", what, lua_tostring(L, -1), EntityKindName(e.kind), expected);
}

int Position(lua_State* L) {
  EntityStore* store = nullptr;
  EntityRef e;
  const int i = Resolve(L, "position", &store, &e);
  const Vec3 p = store->Position(e, i);
  lua_pushnumber(L, p.x());
  lua_pushnumber(L, p.y());
  lua_pushnumber(L, p.z());
  return 3;
}

int Heading(lua_State* L) {
  EntityStore* store = nullptr;
  EntityRef e;
  const int i = Resolve(L, "heading", &store, &e);
  lua_pushnumber(L, WrapSigned(store->Yaw(e, i)));
  return 1;
}

int SetPose(lua_State* L) {
  EntityStore* store = nullptr;
  EntityRef e;
  const int i = Resolve(L, "set_pose", &store, &e);
  const double x = luaL_checknumber(L, 2), y = luaL_checknumber(L, 3);
  const double yaw = lua_isnoneornil(L, 4) ? store->Yaw(e, i) : luaL_checknumber(L, 4);
  // A non-finite pose would poison the physics and every grid that indexes by position.
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(yaw))
    return luaL_error(L, "set_pose: x, y and yaw must be finite numbers, got %f, %f, %f", x, y, yaw);
  // ARGoS moves static entities only while building the arena: their place is baked into
  // the spatial structures sensors use.
  if (e.kind != EntityKind::FootBot && e.kind != EntityKind::Light && !store->Obstacle(i).movable &&
      LoopContextOf(L)->tick > 0)
    return luaL_error(L, "set_pose: %s '%s' is static: it can only be moved before the first step (in init)",
                      EntityKindName(e.kind), store->Obstacle(i).id.c_str());
  store->SetPose(e, i, {x, y, yaw});
  return 0;
}

int Movable(lua_State* L) {
  EntityStore* store = nullptr;
  EntityRef e;
  const int i = Resolve(L, "movable", &store, &e);
  lua_pushboolean(L, store->Movable(e, i));
  return 1;
}

// ---- LEDs
int LedCountFn(lua_State* L) {
  EntityStore* store = nullptr;
  EntityRef e;
  const int i = Resolve(L, "led_count", &store, &e);
  lua_pushinteger(L, store->LedCount(e, i));
  return 1;
}

int LedIndex(lua_State* L, int arg, const char* what, int count) {
  lua_Integer k = luaL_checkinteger(L, arg);
  if (k < 1 || k > count) {
    lua_getiuservalue(L, 1, 1);
    return luaL_error(L, "%s: LED index %d out of range: '%s' has %d LEDs", what, static_cast<int>(k),
                      lua_tostring(L, -1), count);
  }
  return static_cast<int>(k - 1);
}

int LedColor(lua_State* L) {
  EntityStore* store = nullptr;
  EntityRef e;
  const int i = Resolve(L, "led_color", &store, &e);
  const Color c = store->Led(e, i, LedIndex(L, 2, "led_color", store->LedCount(e, i)));
  lua_pushinteger(L, c.r);
  lua_pushinteger(L, c.g);
  lua_pushinteger(L, c.b);
  return 3;
}

/// A colour from arguments first.. : a name, or three numbers 0-255.
Color CheckColor(lua_State* L, int first, const char* what) {
  if (lua_type(L, first) == LUA_TSTRING) {
    auto c = ParseColor(lua_tostring(L, first));
    if (!c)
      luaL_error(L, "%s: bad colour '%s' (a name such as \"red\", or r, g, b in 0-255)", what, lua_tostring(L, first));
    return c ? *c : Color();
  }
  Color c{0, 0, 0, 255};
  unsigned char* parts[] = {&c.r, &c.g, &c.b};
  for (int k = 0; k < 3; ++k) {
    if (!lua_isnumber(L, first + k))
      luaL_error(L, "%s: bad colour (a name such as \"red\", or r, g, b in 0-255)", what);
    const double v = lua_tonumber(L, first + k);
    if (!(v >= 0 && v <= 255)) luaL_error(L, "%s: colour component %f is not in 0-255", what, v);
    *parts[k] = static_cast<unsigned char>(std::lround(v));
  }
  return c;
}

int SetLedColor(lua_State* L) {
  EntityStore* store = nullptr;
  EntityRef e;
  const int i = Resolve(L, "set_led_color", &store, &e);
  const int count = store->LedCount(e, i);
  // (color) | (i, color) | (r, g, b) | (i, r, g, b)
  const int args = lua_gettop(L) - 1;
  const bool indexed = args == 2 || args == 4;
  const int k = indexed ? LedIndex(L, 2, "set_led_color", count) : -1;
  const Color c = CheckColor(L, indexed ? 3 : 2, "set_led_color");
  if (count == 0) return WrongKind(L, "set_led_color", e, "an entity with LEDs");
  store->SetLed(e, i, k, c);
  return 0;
}

// ---- lights
int CheckLight(lua_State* L, const char* what, EntityStore** store) {
  EntityRef e;
  const int i = Resolve(L, what, store, &e);
  if (e.kind != EntityKind::Light) WrongKind(L, what, e, "a light");
  return i;
}

int Intensity(lua_State* L) {
  EntityStore* store = nullptr;
  const int i = CheckLight(L, "intensity", &store);
  lua_pushnumber(L, store->Light(i).intensity);
  return 1;
}

int SetIntensity(lua_State* L) {
  EntityStore* store = nullptr;
  const int i = CheckLight(L, "set_intensity", &store);
  const double v = luaL_checknumber(L, 2);
  if (!std::isfinite(v) || v < 0)
    return luaL_error(L, "set_intensity: intensity must be a finite number >= 0, got %f", v);
  store->SetLightIntensity(i, v);
  return 0;
}

int LightColor(lua_State* L) {
  EntityStore* store = nullptr;
  const int i = CheckLight(L, "color", &store);
  const Color c = store->Light(i).color;
  lua_pushinteger(L, c.r);
  lua_pushinteger(L, c.g);
  lua_pushinteger(L, c.b);
  return 3;
}

int SetLightColor(lua_State* L) {
  EntityStore* store = nullptr;
  const int i = CheckLight(L, "set_color", &store);
  store->SetLightColor(i, CheckColor(L, 2, "set_color"));
  return 0;
}

// ---- experiment.entities / remove_entity (add_entity: loop_add_entity.cpp)
int Entities(lua_State* L) {
  EntityStore* store = LoopContextOf(L)->entities;
  EntityKind kind = EntityKind::FootBot;
  const bool all = lua_isnoneornil(L, 1);
  if (!all && !ParseEntityKind(luaL_checkstring(L, 1), &kind))
    return luaL_error(L, "entities: unknown kind '%s' (foot-bot, box, cylinder, light, or nil for all)",
                      lua_tostring(L, 1));
  const auto& all_refs = store->All();
  lua_createtable(L, static_cast<int>(all_refs.size()), 0);
  lua_Integer n = 0;
  for (const EntityRef& e : all_refs) {
    if (!all && e.kind != kind) continue;
    PushEntityHandle(L, e, store->IdOf(e).c_str());
    lua_rawseti(L, -2, ++n);
  }
  return 1;
}

int RemoveEntity(lua_State* L) {
  EntityStore* store = nullptr;
  EntityRef e;
  Resolve(L, "remove_entity", &store, &e);
  if (e.kind == EntityKind::FootBot)
    return luaL_error(L, "remove_entity: foot-bots cannot be removed (r:kill() stops one for good)");
  store->Remove(e);
  return 0;
}

}  // namespace

void OpenEntityApi(lua_State* L, int experiment) {
  experiment = lua_absindex(L, experiment);
  static const luaL_Reg methods[] = {
      {"position", Position},         {"heading", Heading},         {"set_pose", SetPose},
      {"movable", Movable},           {"led_count", LedCountFn},    {"led_color", LedColor},
      {"set_led_color", SetLedColor}, {"intensity", Intensity},     {"set_intensity", SetIntensity},
      {"color", LightColor},          {"set_color", SetLightColor}, {nullptr, nullptr}};
  lua_rawgetp(L, LUA_REGISTRYINDEX, &kHandleMetaKey);
  luaL_setfuncs(L, methods, 0);
  lua_pop(L, 1);
  lua_newtable(L);
  lua_rawsetp(L, LUA_REGISTRYINDEX, &kHandleCacheKey);
  const luaL_Reg api[] = {{"entities", Entities}, {"add_entity", AddEntity}, {"remove_entity", RemoveEntity}};
  for (const luaL_Reg& r : api) {
    lua_pushcfunction(L, r.func);
    lua_setfield(L, experiment, r.name);
  }
}

}  // namespace essaim
