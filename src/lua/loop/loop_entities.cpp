// Loop functions' reach over every entity (docs/loop-functions.md, ARGoS's CSpace):
// experiment.entities / add_entity / remove_entity, and the handle methods shared by
// foot-bots, boxes, cylinders and lights (pose, LEDs, light intensity and colour).
// Entity changes go through the World's EntityStore, which raises the "scene changed"
// flag the step turns into a media refresh; they only happen in loop-function stages.
//
// Lua errors longjmp: no C++ object with a destructor lives across a Lua API call that can
// raise. Specs are parsed into LoopFunctions' own scratch defs for that reason.
#include <cmath>
#include <cstring>
#include <lua.hpp>

#include "model/distribute.h"
#include "model/limits.h"

#include "core/color.h"
#include "lua/loop/loop_functions.h"
#include "lua/loop/loop_handles.h"

namespace essaim {

const char kHandleMetaKey = 0, kHandleCacheKey = 0;

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
  const bool ok = lua_topointer(L, -1) == LoopFunctionsOf(L)->handle_meta_;
  lua_pop(L, 1);
  return ok ? static_cast<EntityHandle*>(p) : nullptr;
}

LoopFunctions* LoopFunctionsOf(lua_State* L) {
  // Set by Load in the state's extra space (coroutines inherit a copy): a registry lookup
  // here cost ~200 instructions per handle call.
  return *static_cast<LoopFunctions**>(lua_getextraspace(L));
}

struct LoopEntities {
  static LoopFunctions* Self(lua_State* L) { return LoopFunctionsOf(L); }

  /// The live entity behind argument 1: its ref and current index; raises otherwise.
  static int Resolve(lua_State* L, const char* what, LoopFunctions** lf, EntityRef* ref) {
    EntityHandle* h = ToEntityHandle(L, 1);
    if (!h) return luaL_error(L, "%s: entity handle expected (call it as handle:%s(...))", what, what);
    *lf = Self(L);
    *ref = h->ref;
    const int index = (*lf)->entities_->IndexOf(h->ref);
    if (index < 0) {
      lua_getiuservalue(L, 1, 1);
      return luaL_error(L, "%s: %s '%s' was removed by experiment.remove_entity", what, EntityKindName(h->ref.kind),
                        lua_tostring(L, -1));
    }
    return index;
  }
  static bool IsObstacle(const EntityRef& e) { return e.kind == EntityKind::Box || e.kind == EntityKind::Cylinder; }
  static int WrongKind(lua_State* L, const char* what, const EntityRef& e, const char* expected) {
    lua_getiuservalue(L, 1, 1);
    return luaL_error(L, "%s: '%s' is a %s, not %s", what, lua_tostring(L, -1), EntityKindName(e.kind), expected);
  }

  static int Position(lua_State* L) {
    LoopFunctions* lf = nullptr;
    EntityRef e;
    const int i = Resolve(L, "position", &lf, &e);
    Vec3 p;
    if (e.kind == EntityKind::FootBot) {
      Pose2 pose = lf->physics_->RobotPose(i);
      p = Vec3(pose.x, pose.y, lf->entities_->scene().robots[i].z);
    } else if (e.kind == EntityKind::Light) {
      p = lf->entities_->scene().lights[i].position;
    } else {
      Pose2 pose = lf->physics_->ObstaclePose(i);
      p = Vec3(pose.x, pose.y, lf->entities_->scene().obstacles[i].z);
    }
    lua_pushnumber(L, p.x());
    lua_pushnumber(L, p.y());
    lua_pushnumber(L, p.z());
    return 3;
  }
  static double Yaw(LoopFunctions* lf, const EntityRef& e, int i) {
    if (e.kind == EntityKind::FootBot) return lf->physics_->RobotPose(i).yaw;
    if (e.kind == EntityKind::Light) return 0;
    return lf->physics_->ObstaclePose(i).yaw;
  }
  static int Heading(lua_State* L) {
    LoopFunctions* lf = nullptr;
    EntityRef e;
    const int i = Resolve(L, "heading", &lf, &e);
    lua_pushnumber(L, WrapSigned(Yaw(lf, e, i)));
    return 1;
  }
  static int SetPose(lua_State* L) {
    LoopFunctions* lf = nullptr;
    EntityRef e;
    const int i = Resolve(L, "set_pose", &lf, &e);
    const double x = luaL_checknumber(L, 2), y = luaL_checknumber(L, 3);
    const double yaw = lua_isnoneornil(L, 4) ? Yaw(lf, e, i) : luaL_checknumber(L, 4);
    // A non-finite pose would poison the physics and every grid that indexes by position.
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(yaw))
      return luaL_error(L, "set_pose: x, y and yaw must be finite numbers, got %f, %f, %f", x, y, yaw);
    Model& scene = lf->entities_->scene();
    if (e.kind == EntityKind::FootBot) {
      lf->physics_->SetRobotPose(i, {x, y, yaw});
    } else if (e.kind == EntityKind::Light) {
      scene.lights[i].position.x() = x, scene.lights[i].position.y() = y;
    } else {
      const ObstacleDef& o = scene.obstacles[i];
      // ARGoS moves static entities only while building the arena: their place is baked
      // into the spatial structures sensors use.
      if (!o.movable && lf->tick_ > 0)
        return luaL_error(L, "set_pose: %s '%s' is static: it can only be moved before the first step (in init)",
                          EntityKindName(e.kind), o.id.c_str());
      lf->entities_->SetObstaclePose(i, {x, y, yaw});
    }
    lf->entities_->MarkChanged(false);
    return 0;
  }
  static int Movable(lua_State* L) {
    LoopFunctions* lf = nullptr;
    EntityRef e;
    const int i = Resolve(L, "movable", &lf, &e);
    bool movable = e.kind == EntityKind::FootBot || (IsObstacle(e) && lf->entities_->scene().obstacles[i].movable);
    lua_pushboolean(L, movable);
    return 1;
  }

  // ---- LEDs
  static int LedCount(LoopFunctions* lf, const EntityRef& e, int i) {
    if (e.kind == EntityKind::FootBot) return footbot::kLedCount;
    if (IsObstacle(e)) return static_cast<int>(lf->entities_->scene().obstacles[i].leds.size());
    return 0;
  }
  static Color* LedSlot(LoopFunctions* lf, const EntityRef& e, int i, int k) {
    if (e.kind == EntityKind::FootBot) return &(*lf->robots_)[i].leds[k];
    return &lf->entities_->scene().obstacles[i].leds[k].color;
  }
  static int LedCountFn(lua_State* L) {
    LoopFunctions* lf = nullptr;
    EntityRef e;
    const int i = Resolve(L, "led_count", &lf, &e);
    lua_pushinteger(L, LedCount(lf, e, i));
    return 1;
  }
  static int LedIndex(lua_State* L, int arg, const char* what, int count) {
    lua_Integer k = luaL_checkinteger(L, arg);
    if (k < 1 || k > count) {
      lua_getiuservalue(L, 1, 1);
      return luaL_error(L, "%s: LED index %d out of range: '%s' has %d LEDs", what, static_cast<int>(k),
                        lua_tostring(L, -1), count);
    }
    return static_cast<int>(k - 1);
  }
  static int LedColor(lua_State* L) {
    LoopFunctions* lf = nullptr;
    EntityRef e;
    const int i = Resolve(L, "led_color", &lf, &e);
    const Color c = *LedSlot(lf, e, i, LedIndex(L, 2, "led_color", LedCount(lf, e, i)));
    lua_pushinteger(L, c.r);
    lua_pushinteger(L, c.g);
    lua_pushinteger(L, c.b);
    return 3;
  }
  /// A colour from arguments first.. : a name, or three numbers 0-255.
  static Color CheckColor(lua_State* L, int first, const char* what) {
    if (lua_type(L, first) == LUA_TSTRING) {
      auto c = ParseColor(lua_tostring(L, first));
      if (!c) luaL_error(L, "%s: bad colour '%s' (a name such as \"red\", or r, g, b in 0-255)", what, lua_tostring(L, first));
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
  static int SetLedColor(lua_State* L) {
    LoopFunctions* lf = nullptr;
    EntityRef e;
    const int i = Resolve(L, "set_led_color", &lf, &e);
    const int count = LedCount(lf, e, i);
    // (color) | (i, color) | (r, g, b) | (i, r, g, b)
    const int args = lua_gettop(L) - 1;
    const bool indexed = args == 2 || args == 4;
    const int k = indexed ? LedIndex(L, 2, "set_led_color", count) : -1;
    const Color c = CheckColor(L, indexed ? 3 : 2, "set_led_color");
    if (count == 0) return WrongKind(L, "set_led_color", e, "an entity with LEDs");
    for (int j = 0; j < count; ++j)
      if (k < 0 || j == k) *LedSlot(lf, e, i, j) = c;
    lf->entities_->MarkChanged(false);  // cameras see it from the next sense
    return 0;
  }

  // ---- lights
  static LightDef& CheckLight(lua_State* L, const char* what) {
    LoopFunctions* lf = nullptr;
    EntityRef e;
    const int i = Resolve(L, what, &lf, &e);
    if (e.kind != EntityKind::Light) WrongKind(L, what, e, "a light");
    return lf->entities_->scene().lights[i];
  }
  static int Intensity(lua_State* L) {
    lua_pushnumber(L, CheckLight(L, "intensity").intensity);
    return 1;
  }
  static int SetIntensity(lua_State* L) {
    LightDef& l = CheckLight(L, "set_intensity");
    const double v = luaL_checknumber(L, 2);
    if (!std::isfinite(v) || v < 0) return luaL_error(L, "set_intensity: intensity must be a finite number >= 0, got %f", v);
    l.intensity = v;
    Self(L)->entities_->MarkChanged(false);
    return 0;
  }
  static int LightColor(lua_State* L) {
    const Color c = CheckLight(L, "color").color;
    lua_pushinteger(L, c.r);
    lua_pushinteger(L, c.g);
    lua_pushinteger(L, c.b);
    return 3;
  }
  static int SetLightColor(lua_State* L) {
    LightDef& l = CheckLight(L, "set_color");
    l.color = CheckColor(L, 2, "set_color");
    Self(L)->entities_->MarkChanged(false);
    return 0;
  }

  // ---- experiment.entities / add_entity / remove_entity
  static const char* IdOf(LoopFunctions* lf, const EntityRef& e) {
    const Model& s = lf->entities_->scene();
    const int i = lf->entities_->IndexOf(e);
    if (e.kind == EntityKind::FootBot) return s.robots[i].id.c_str();
    if (e.kind == EntityKind::Light) return s.lights[i].id.c_str();
    return s.obstacles[i].id.c_str();
  }
  static int Entities(lua_State* L) {
    LoopFunctions* lf = Self(L);
    EntityKind kind = EntityKind::FootBot;
    const bool all = lua_isnoneornil(L, 1);
    if (!all && !ParseEntityKind(luaL_checkstring(L, 1), &kind))
      return luaL_error(L, "entities: unknown kind '%s' (foot-bot, box, cylinder, light, or nil for all)",
                        lua_tostring(L, 1));
    const auto& all_refs = lf->entities_->All();
    lua_createtable(L, static_cast<int>(all_refs.size()), 0);
    lua_Integer n = 0;
    for (const EntityRef& e : all_refs) {
      if (!all && e.kind != kind) continue;
      PushEntityHandle(L, e, IdOf(lf, e));
      lua_rawseti(L, -2, ++n);
    }
    return 1;
  }

  // Raw field access: a spec's metamethods never run.
  static int Field(lua_State* L, const char* name) {
    lua_pushstring(L, name);
    return lua_rawget(L, 2);
  }
  static double Number(lua_State* L, const char* name, double def, bool required) {
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
  static Vec3 Triple(lua_State* L, const char* name, int min_count) {
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
  static Color ColorField(lua_State* L, int idx, const char* name) {
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
  static void CheckMedium(lua_State* L, LoopFunctions* lf, const std::string& medium) {
    for (const LedMediumDef& m : lf->model_->led_media)
      if (m.id == medium) return;
    luaL_error(L, "add_entity: medium '%s' is not declared in <media> (<led id=\"%s\"/>)", medium.c_str(), medium.c_str());
  }
  static void SetString(lua_State* L, const char* name, std::string* out, bool required) {
    const int t = Field(L, name);
    if (t == LUA_TNIL && required) luaL_error(L, "add_entity: spec needs '%s'", name);
    if (t != LUA_TNIL && t != LUA_TSTRING) luaL_error(L, "add_entity: '%s' must be a string", name);
    if (t == LUA_TSTRING) *out = lua_tostring(L, -1);
    lua_pop(L, 1);
  }
  static void ParseLeds(lua_State* L, LoopFunctions* lf, ObstacleDef* o) {
    if (Field(L, "leds") == LUA_TNIL) return lua_pop(L, 1);
    if (!lua_istable(L, -1)) luaL_error(L, "add_entity: 'leds' must be an array of {offset = {x, y, z}, color = ...}");
    const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, -1));
    for (lua_Integer k = 1; k <= n; ++k) {
      if (lua_rawgeti(L, -1, k) != LUA_TTABLE) luaL_error(L, "add_entity: leds[%d] must be a table", static_cast<int>(k));
      LedDef led;
      lua_pushliteral(L, "offset");
      if (lua_rawget(L, -2) == LUA_TNIL) lua_pop(L, 1);
      else led.offset = Triple(L, "offset", 3);
      lua_pushliteral(L, "anchor");
      if (lua_rawget(L, -2) != LUA_TNIL && (!lua_isstring(L, -1) || std::strcmp(lua_tostring(L, -1), "origin")))
        luaL_error(L, "add_entity: leds[%d].anchor: boxes and cylinders have one anchor, \"origin\"", static_cast<int>(k));
      lua_pop(L, 1);
      lua_pushliteral(L, "color");
      if (lua_rawget(L, -2) != LUA_TNIL) led.color = ColorField(L, -1, "color");
      lua_pop(L, 2);
      o->leds.push_back(led);
    }
    lua_pop(L, 1);
    if (!o->leds.empty()) {
      SetString(L, "medium", &o->led_medium, true);
      CheckMedium(L, lf, o->led_medium);
    }
  }
  /// Refuses what the .argos loader refuses: sizes over the limits, a base below the floor,
  /// a footprint overlapping a foot-bot where it stands now.
  /// Raises "add_entity: " + `problem` at the script's line unless it is "". The message is
  /// on Lua's stack before `problem` goes: lua_error's longjmp skips C++ destructors.
  static void RaiseIf(lua_State* L, std::string&& problem) {
    if (problem.empty()) return;
    luaL_where(L, 1);
    lua_pushfstring(L, "add_entity: %s", problem.c_str());
    lua_concat(L, 2);
    std::string().swap(problem);
    lua_error(L);
  }
  static void CheckObstacle(lua_State* L, LoopFunctions* lf, const ObstacleDef& o) {
    RaiseIf(L, ObstacleProblem(o, lf->entities_->scene().experiment.limits));
    const Footprint f = ObstacleFootprint(o);
    const std::vector<RobotDef>& robots = lf->entities_->scene().robots;
    for (size_t i = 0; i < robots.size(); ++i) {
      const Pose2 pose = lf->physics_->RobotPose(static_cast<int>(i));
      Footprint robot;
      robot.center = {pose.x, pose.y};
      robot.radius = footbot::kRadius;
      if (FootprintsOverlap(f, robot)) luaL_error(L, "add_entity: it would overlap foot-bot '%s'", robots[i].id.c_str());
    }
  }
  /// Refuses one entity more than the experiment's limit.
  static void CheckRoom(lua_State* L, LoopFunctions* lf) {
    const Model& scene = lf->entities_->scene();
    RaiseIf(L, EntityCountProblem(scene.robots.size() + scene.obstacles.size() + scene.lights.size() + 1,
                                  scene.experiment.limits));
  }
  static int AddEntity(lua_State* L) {
    LoopFunctions* lf = Self(L);
    EntityKind kind;
    const char* kind_name = luaL_checkstring(L, 1);
    if (!ParseEntityKind(kind_name, &kind))
      return luaL_error(L, "add_entity: unknown kind '%s' (box, cylinder or light)", kind_name);
    if (kind == EntityKind::FootBot)
      return luaL_error(L, "add_entity: adding foot-bots is not supported (declare them in the .argos file)");
    luaL_checktype(L, 2, LUA_TTABLE);
    lua_settop(L, 2);
    lua_Debug ar;
    const int line = lua_getstack(L, 1, &ar) && lua_getinfo(L, "l", &ar) ? ar.currentline : 0;

    std::string* id;
    if (kind == EntityKind::Light) {
      LightDef& l = lf->light_spec_;
      l = LightDef();
      id = &l.id;
      l.loc = {lf->script_, line, "add_entity"};
      l.position = (Field(L, "position") == LUA_TNIL ? (luaL_error(L, "add_entity: spec needs 'position'"), Vec3())
                                                     : Triple(L, "position", 2));
      if (Field(L, "color") == LUA_TNIL) luaL_error(L, "add_entity: spec needs 'color'");
      l.color = ColorField(L, -1, "color");
      lua_pop(L, 1);
      l.intensity = Number(L, "intensity", 1.0, false);
      if (l.intensity < 0) luaL_error(L, "add_entity: 'intensity' must be >= 0");
      SetString(L, "medium", &l.medium, true);
      CheckMedium(L, lf, l.medium);
    } else {
      ObstacleDef& o = lf->obstacle_spec_;
      o = ObstacleDef();
      id = &o.id;
      o.kind = kind == EntityKind::Box ? ShapeKind::Box : ShapeKind::Cylinder;
      o.loc = {lf->script_, line, "add_entity"};
      if (Field(L, "position") == LUA_TNIL) luaL_error(L, "add_entity: spec needs 'position'");
      const Vec3 p = Triple(L, "position", 2);
      o.pose = {p.x(), p.y(), DegToRad(Number(L, "orientation", 0, false))};
      o.z = p.z();
      if (kind == EntityKind::Box) {
        if (Field(L, "size") == LUA_TNIL) luaL_error(L, "add_entity: a box spec needs 'size' = {x, y, z}");
        const Vec3 s = Triple(L, "size", 3);
        if (s.minCoeff() <= 0) luaL_error(L, "add_entity: size components must be > 0");
        o.size_x = s.x(), o.size_y = s.y(), o.height = s.z();
      } else {
        o.radius = Number(L, "radius", 0, true);
        o.height = Number(L, "height", 0, true);
        if (o.radius <= 0 || o.height <= 0) luaL_error(L, "add_entity: radius and height must be > 0");
      }
      const int t = Field(L, "movable");
      if (t != LUA_TNIL && t != LUA_TBOOLEAN) luaL_error(L, "add_entity: 'movable' must be a boolean");
      o.movable = lua_toboolean(L, -1);
      lua_pop(L, 1);
      if (o.movable) {
        o.mass = Number(L, "mass", 0, true);
        if (o.mass <= 0) luaL_error(L, "add_entity: mass must be > 0 for a movable object");
      }
      ParseLeds(L, lf, &o);
      CheckObstacle(L, lf, o);
    }
    CheckRoom(L, lf);
    SetString(L, "id", id, false);
    if (id->empty()) {
      // Generated ids follow the kind and a counter, skipping any taken.
      for (int n = static_cast<int>(lf->entities_->All().size());; ++n) {
        *id = std::string(kind_name) + "_" + std::to_string(n);
        if (!lf->entities_->HasId(*id)) break;
      }
    } else if (lf->entities_->HasId(*id)) {
      return luaL_error(L, "add_entity: id '%s' is already used", id->c_str());
    }
    const EntityRef e = kind == EntityKind::Light ? lf->entities_->AddLight(lf->light_spec_)
                                                  : lf->entities_->AddObstacle(lf->obstacle_spec_);
    PushEntityHandle(L, e, IdOf(lf, e));
    return 1;
  }
  static int RemoveEntity(lua_State* L) {
    LoopFunctions* lf = nullptr;
    EntityRef e;
    Resolve(L, "remove_entity", &lf, &e);
    if (e.kind == EntityKind::FootBot)
      return luaL_error(L, "remove_entity: foot-bots cannot be removed (r:kill() stops one for good)");
    lf->entities_->Remove(e);
    return 0;
  }
};

void OpenEntityApi(lua_State* L, int experiment) {
  experiment = lua_absindex(L, experiment);
  static const luaL_Reg methods[] = {
      {"position", LoopEntities::Position},     {"heading", LoopEntities::Heading},
      {"set_pose", LoopEntities::SetPose},      {"movable", LoopEntities::Movable},
      {"led_count", LoopEntities::LedCountFn},  {"led_color", LoopEntities::LedColor},
      {"set_led_color", LoopEntities::SetLedColor}, {"intensity", LoopEntities::Intensity},
      {"set_intensity", LoopEntities::SetIntensity}, {"color", LoopEntities::LightColor},
      {"set_color", LoopEntities::SetLightColor}, {nullptr, nullptr}};
  lua_rawgetp(L, LUA_REGISTRYINDEX, &kHandleMetaKey);
  luaL_setfuncs(L, methods, 0);
  lua_pop(L, 1);
  lua_newtable(L);
  lua_rawsetp(L, LUA_REGISTRYINDEX, &kHandleCacheKey);
  const luaL_Reg api[] = {{"entities", LoopEntities::Entities},
                          {"add_entity", LoopEntities::AddEntity},
                          {"remove_entity", LoopEntities::RemoveEntity}};
  for (const luaL_Reg& r : api) {
    lua_pushcfunction(L, r.func);
    lua_setfield(L, experiment, r.name);
  }
}

}  // namespace essaim
