#include "lua/loop_functions.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <lua.hpp>

#include "core/color.h"
#include "core/json.h"
#include "core/paths.h"
#include "core/strings.h"
#include "lua/lua_math_types.h"
#include "lua/lua_random.h"

namespace essaim {

// Registry keys by address: every handle call reaches its context without interning a
// name (the foraging rules make a few per robot per tick).
const char kSelfKey = 0, kHandleMetaKey = 0;

struct LoopFunctionsAccess {
  static LoopFunctions* Self(lua_State* L) {
    lua_rawgetp(L, LUA_REGISTRYINDEX, &kSelfKey);
    auto* lf = static_cast<LoopFunctions*>(lua_touserdata(L, -1));
    lua_pop(L, 1);
    return lf;
  }
  static int RobotIndex(lua_State* L) {
    void* p = lua_touserdata(L, 1);
    bool ok = p && lua_getmetatable(L, 1);
    if (ok) {
      lua_rawgetp(L, LUA_REGISTRYINDEX, &kHandleMetaKey);
      ok = lua_rawequal(L, -1, -2);
      lua_pop(L, 2);
    }
    if (!ok) luaL_typeerror(L, 1, "robot handle");
    return *static_cast<int*>(p);
  }
  static int Position(lua_State* L) {
    LoopFunctions* lf = Self(L);
    Pose2 p = lf->physics_->RobotPose(RobotIndex(L));
    lua_pushnumber(L, p.x);
    lua_pushnumber(L, p.y);
    return 2;
  }
  static int Heading(lua_State* L) {
    lua_pushnumber(L, WrapSigned(Self(L)->physics_->RobotPose(RobotIndex(L)).yaw));
    return 1;
  }
  static int SetPose(lua_State* L) {
    LoopFunctions* lf = Self(L);
    int i = RobotIndex(L);
    const double x = luaL_checknumber(L, 2), y = luaL_checknumber(L, 3), yaw = luaL_optnumber(L, 4, 0);
    // A non-finite pose would poison the physics and every grid that indexes by position.
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(yaw))
      return luaL_error(L, "set_pose: x, y and yaw must be finite numbers, got %f, %f, %f", x, y, yaw);
    lf->physics_->SetRobotPose(i, {x, y, yaw});
    return 0;
  }
  static int Battery(lua_State* L) {
    LoopFunctions* lf = Self(L);
    int i = RobotIndex(L);
    lua_pushnumber(L, (*lf->robots_)[i].battery.charge / lf->model_->robots[i].battery.full_charge);
    return 1;
  }
  static int SetBattery(lua_State* L) {
    LoopFunctions* lf = Self(L);
    int i = RobotIndex(L);
    double c = luaL_checknumber(L, 2);
    if (c < 0 || c > 1) return luaL_error(L, "set_battery: charge must be in [0, 1], got %f", c);
    (*lf->robots_)[i].battery.charge = c * lf->model_->robots[i].battery.full_charge;
    return 0;
  }
  static int Alive(lua_State* L) {
    lua_pushboolean(L, (*Self(L)->robots_)[RobotIndex(L)].alive);
    return 1;
  }
  static int Kill(lua_State* L) {
    LoopFunctions* lf = Self(L);
    int i = RobotIndex(L);
    RobotState& r = (*lf->robots_)[i];
    r.alive = false;
    r.wheel_left = r.wheel_right = 0;
    lf->physics_->FreezeRobot(i);
    return 0;
  }
  static int ControllerOk(lua_State* L) {
    lua_pushboolean(L, (*Self(L)->robots_)[RobotIndex(L)].controller_ok);
    return 1;
  }
  static int Led(lua_State* L) {
    LoopFunctions* lf = Self(L);
    int i = RobotIndex(L);
    lua_Integer k = luaL_checkinteger(L, 2);
    if (k < 1 || k > footbot::kLedCount) return luaL_error(L, "led index must be 1..13");
    const Color& c = (*lf->robots_)[i].leds[k - 1];
    lua_pushinteger(L, c.r);
    lua_pushinteger(L, c.g);
    lua_pushinteger(L, c.b);
    return 3;
  }
  static int HandleIndex(lua_State* L) {
    LoopFunctions* lf = Self(L);
    int i = RobotIndex(L);
    const char* k = luaL_checkstring(L, 2);
    if (!std::strcmp(k, "id")) return lua_pushstring(L, lf->model_->robots[i].id.c_str()), 1;
    if (!std::strcmp(k, "index")) return lua_pushinteger(L, i + 1), 1;
    lua_getmetatable(L, 1);
    lua_pushvalue(L, 2);
    lua_rawget(L, -2);
    return 1;
  }
  static int Timeseries(lua_State* L) {
    LoopFunctions* lf = Self(L);
    luaL_checktype(L, 1, LUA_TTABLE);
    lua_Integer n = luaL_len(L, 1);
    bool first = lf->series_.columns.empty() && lf->series_.rows.empty();
    if (!first && static_cast<size_t>(n) != lf->series_.columns.size())
      return luaL_error(L, "timeseries: row has %d columns, the first row had %d", (int)n, (int)lf->series_.columns.size());
    // Checked whole before anything is kept: luaL_error jumps over C++ destructors, so no
    // C++ object may be alive when it raises (a half-built row leaked), and a bad row must
    // not leave half its columns behind.
    for (lua_Integer k = 1; k <= n; ++k) {
      lua_rawgeti(L, 1, k);
      if (!lua_istable(L, -1)) return luaL_error(L, "timeseries: each item must be {name, value}");
      lua_rawgeti(L, -1, 1);
      lua_rawgeti(L, -2, 2);
      const char* name = lua_tostring(L, -2);
      if (!name || !lua_isnumber(L, -1)) return luaL_error(L, "timeseries: item %d must be {name, number}", (int)k);
      if (!first && lf->series_.columns[k - 1].compare(name) != 0)
        return luaL_error(L, "timeseries: column %d is '%s', expected '%s'", (int)k, name, lf->series_.columns[k - 1].c_str());
      lua_pop(L, 3);
    }
    std::vector<double> row;
    row.reserve(static_cast<size_t>(n));
    for (lua_Integer k = 1; k <= n; ++k) {
      lua_rawgeti(L, 1, k);
      lua_rawgeti(L, -1, 1);
      lua_rawgeti(L, -2, 2);
      if (first) lf->series_.columns.push_back(lua_tostring(L, -2));
      row.push_back(lua_tonumber(L, -1));
      lua_pop(L, 3);
    }
    lf->series_.rows.push_back(std::move(row));
    return 0;
  }
};

namespace {
// _G[name] read raw: these lookups run outside any pcall, so a script's metamethod on _G
// must not run there.
int RawGlobal(lua_State* L, const char* name) {
  lua_rawgeti(L, LUA_REGISTRYINDEX, LUA_RIDX_GLOBALS);
  lua_pushstring(L, name);
  int type = lua_rawget(L, -2);
  lua_remove(L, -2);
  return type;
}

int Traceback(lua_State* L) {
  const char* msg = lua_tostring(L, 1);
  luaL_traceback(L, L, msg ? msg : "(error object is not a string)", 1);
  return 1;
}

int LoopLog(lua_State* L) {
  auto* log = static_cast<std::string*>(lua_touserdata(L, lua_upvalueindex(1)));
  char stream = static_cast<char>(lua_tointeger(L, lua_upvalueindex(2)));
  *log += stream;
  int n = lua_gettop(L);
  for (int i = 1; i <= n; ++i) {
    if (lua_type(L, i) == LUA_TNUMBER) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%g", lua_tonumber(L, i));
      *log += buf;
    } else if (lua_type(L, i) == LUA_TBOOLEAN) {
      *log += lua_toboolean(L, i) ? "1" : "0";
    } else {
      *log += luaL_tolstring(L, i, nullptr);
      lua_pop(L, 1);
    }
    if (stream == 'P' && i < n) *log += '\t';
  }
  *log += '\n';
  return 0;
}

std::string LuaString(lua_State* L, int idx) {
  size_t len = 0;
  const char* p = lua_tolstring(L, idx, &len);
  return std::string(p, len);  // whole, NUL bytes included
}

// A Lua value as JSON: a table with keys 1..n only is an array (empty → []); other
// tables are objects with keys sorted, so metrics.json does not depend on hashing.
// JSON has no NaN or infinity: those become null and their key path goes to `nonfinite`.
bool ToJson(lua_State* L, int idx, Json* out, int depth, const std::string& where,
            std::vector<std::string>* nonfinite, std::string* error) {
  idx = lua_absindex(L, idx);
  if (depth > 32) {
    *error = "table nested too deep (cycle?)";
    return false;
  }
  switch (lua_type(L, idx)) {
    case LUA_TNIL: *out = nullptr; return true;
    case LUA_TBOOLEAN: *out = lua_toboolean(L, idx) != 0; return true;
    case LUA_TNUMBER:
      if (lua_isinteger(L, idx)) {
        *out = static_cast<int64_t>(lua_tointeger(L, idx));
      } else {
        double v = lua_tonumber(L, idx);
        if (std::isfinite(v)) *out = v;
        else *out = nullptr, nonfinite->push_back(where);
      }
      return true;
    case LUA_TSTRING: *out = LuaString(L, idx); return true;
    case LUA_TTABLE: {
      lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, idx));
      size_t count = 0;
      bool all_int = true;
      std::vector<std::string> keys;
      lua_pushnil(L);
      while (lua_next(L, idx)) {
        ++count;
        if (lua_type(L, -2) == LUA_TSTRING) keys.push_back(LuaString(L, -2));
        else if (lua_isinteger(L, -2)) keys.push_back(std::to_string(lua_tointeger(L, -2)));
        else {
          lua_pop(L, 2);
          *error = "table keys must be strings or integers";
          return false;
        }
        all_int &= lua_isinteger(L, -2) != 0;
        lua_pop(L, 1);
      }
      // A metatable field __jsontype = "array" | "object" settles empty or ambiguous tables.
      std::string forced;
      if (luaL_getmetafield(L, idx, "__jsontype") != LUA_TNIL) {
        if (lua_type(L, -1) == LUA_TSTRING) forced = lua_tostring(L, -1);
        lua_pop(L, 1);
      }
      bool as_array = forced.empty() ? count == static_cast<size_t>(n) && all_int : forced == "array";
      if (as_array) {
        *out = Json::array();
        for (lua_Integer k = 1; k <= n; ++k) {
          lua_rawgeti(L, idx, k);
          Json v;
          bool ok = ToJson(L, -1, &v, depth + 1, where + "[" + std::to_string(k) + "]", nonfinite, error);
          lua_pop(L, 1);
          if (!ok) return false;
          out->push_back(std::move(v));
        }
        return true;
      }
      std::sort(keys.begin(), keys.end());
      *out = Json::object();
      for (const std::string& k : keys) {
        // Keys were collected as text; integer keys are looked up as integers.
        auto as_int = ParseInt(k);
        bool found = false;
        if (as_int) {
          found = lua_rawgeti(L, idx, *as_int) != LUA_TNIL;
          if (!found) lua_pop(L, 1);
        }
        if (!found) {
          lua_pushlstring(L, k.data(), k.size());
          lua_gettable(L, idx);
        }
        Json v;
        bool ok = ToJson(L, -1, &v, depth + 1, where.empty() ? k : where + "." + k, nonfinite, error);
        lua_pop(L, 1);
        if (!ok) return false;
        (*out)[k] = std::move(v);
      }
      return true;
    }
    default:
      *error = std::string("cannot write a ") + luaL_typename(L, idx) + " to JSON";
      return false;
  }
}
}  // namespace

LoopFunctions::~LoopFunctions() {
  CloseGuardedState(&guard_);
}

bool LoopFunctions::Load(const Model& model, std::vector<RobotState>* robots, PhysicsWorld* physics,
                         const std::string& output_dir, std::string* error) {
  model_ = &model;
  robots_ = robots;
  physics_ = physics;
  script_ = model.loop_functions.script;
  if (script_.empty()) return true;
  guard_.name = "loop functions";
  L_ = NewGuardedState(&guard_, limits_);
  if (!L_) {
    *error = "loop functions: cannot create a Lua state";
    return false;
  }
  lua_State* L = L_;
  OpenGuardedLibraries(L, limits_.sandbox);
  lua_pushlightuserdata(L, this);
  lua_rawsetp(L, LUA_REGISTRYINDEX, &kSelfKey);
  lua_pushcfunction(L, Traceback);
  traceback_ref_ = luaL_ref(L, LUA_REGISTRYINDEX);
  OpenMathTypes(L);
  const std::pair<const char*, char> logs[] = {{"log", 'O'}, {"logerr", 'E'}, {"print", 'P'}};
  for (auto [name, stream] : logs) {
    lua_pushlightuserdata(L, &log_);
    lua_pushinteger(L, stream == 'P' ? 'O' : stream);
    lua_pushcclosure(L, LoopLog, 2);
    lua_setglobal(L, name);
  }
  {
    // math.random seeded from the experiment, like the controllers'.
    uint64_t s = DeriveSeed(model.experiment.seed, StreamKind::LoopFunctions, 1);
    lua_getglobal(L, "math");
    lua_getfield(L, -1, "randomseed");
    lua_pushinteger(L, static_cast<lua_Integer>(s & 0x7fffffffffffffffull));
    lua_call(L, 1, 0);
    lua_pop(L, 1);
  }
  static const luaL_Reg handle_methods[] = {
      {"position", LoopFunctionsAccess::Position}, {"heading", LoopFunctionsAccess::Heading},
      {"set_pose", LoopFunctionsAccess::SetPose},  {"battery", LoopFunctionsAccess::Battery},
      {"set_battery", LoopFunctionsAccess::SetBattery}, {"alive", LoopFunctionsAccess::Alive},
      {"kill", LoopFunctionsAccess::Kill},         {"led", LoopFunctionsAccess::Led},
      {"controller_ok", LoopFunctionsAccess::ControllerOk}, {nullptr, nullptr}};
  lua_newtable(L);  // the robot-handle metatable
  luaL_setfuncs(L, handle_methods, 0);
  lua_pushcfunction(L, LoopFunctionsAccess::HandleIndex);
  lua_setfield(L, -2, "__index");
  lua_rawsetp(L, LUA_REGISTRYINDEX, &kHandleMetaKey);

  lua_newtable(L);  // experiment
  lua_pushinteger(L, 0);
  lua_setfield(L, -2, "tick");
  lua_pushinteger(L, model.experiment.ticks_per_second);
  lua_setfield(L, -2, "ticks_per_second");
  lua_pushinteger(L, static_cast<lua_Integer>(model.experiment.length_ticks));
  lua_setfield(L, -2, "length_ticks");
  lua_pushinteger(L, static_cast<lua_Integer>(model.experiment.seed));
  lua_setfield(L, -2, "seed");
  lua_pushstring(L, output_dir.c_str());
  lua_setfield(L, -2, "output_dir");
  lua_newtable(L);
  for (const auto& kv : model.loop_functions.params) {
    lua_pushstring(L, kv.second.c_str());
    lua_setfield(L, -2, kv.first.c_str());
  }
  lua_setfield(L, -2, "params");
  lua_newtable(L);
  const std::pair<const char*, double> arena[] = {{"size_x", model.arena.size.x()}, {"size_y", model.arena.size.y()},
                                                  {"center_x", model.arena.center.x()}, {"center_y", model.arena.center.y()}};
  for (auto [k, v] : arena) {
    lua_pushnumber(L, v);
    lua_setfield(L, -2, k);
  }
  lua_setfield(L, -2, "arena");
  lua_createtable(L, static_cast<int>(robots->size()), 0);
  for (size_t i = 0; i < robots->size(); ++i) {
    *static_cast<int*>(lua_newuserdatauv(L, sizeof(int), 0)) = static_cast<int>(i);
    lua_rawgetp(L, LUA_REGISTRYINDEX, &kHandleMetaKey);
    lua_setmetatable(L, -2);
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  lua_setfield(L, -2, "robots");
  rng_.Seed(DeriveSeed(model.experiment.seed, StreamKind::LoopFunctions, 0));
  PushRandomTable(L, &rng_);
  lua_setfield(L, -2, "random");
  lua_pushcfunction(L, LoopFunctionsAccess::Timeseries);
  lua_setfield(L, -2, "timeseries");
  lua_pushvalue(L, -1);
  experiment_ref_ = luaL_ref(L, LUA_REGISTRYINDEX);
  lua_setglobal(L, "experiment");

  std::string dir = DirName(script_);
  lua_getglobal(L, "package");
  lua_getfield(L, -1, "path");
  std::string path = (dir.empty() ? std::string("./?.lua;") : dir + "/?.lua;") + lua_tostring(L, -1);
  lua_pop(L, 1);
  lua_pushstring(L, path.c_str());
  lua_setfield(L, -2, "path");
  lua_pop(L, 1);

  if (luaL_loadfile(L, script_.c_str()) != LUA_OK) {
    *error = "loop functions: " + std::string(lua_tostring(L, -1));
    return false;
  }
  return PCall(0, 0, "top level", error);
}

void LoopFunctions::SetTick(uint64_t tick) {
  if (!L_) return;
  // The host's own reference and a raw set, outside any pcall: no global a script rebinds
  // (`experiment = nil`) and no metamethod it adds can make this raise (a Lua panic).
  lua_rawgeti(L_, LUA_REGISTRYINDEX, experiment_ref_);
  lua_pushliteral(L_, "tick");
  lua_pushinteger(L_, static_cast<lua_Integer>(tick));
  lua_rawset(L_, -3);
  lua_pop(L_, 1);
}

bool LoopFunctions::PCall(int nargs, int nresults, const char* what, std::string* error) {
  lua_State* L = L_;
  int fn = lua_gettop(L) - nargs;
  lua_rawgeti(L, LUA_REGISTRYINDEX, traceback_ref_);
  lua_insert(L, fn);
  BeginGuardedCall(&guard_);
  const int status = lua_pcall(L, nargs, nresults, fn);
  std::string stopped = EndGuardedCall(&guard_, status);
  if (status != LUA_OK || !stopped.empty()) {
    const char* msg = lua_tostring(L, -1);
    *error = "loop functions (" + std::string(what) + "): " + (!stopped.empty() ? script_ + ": " + stopped : msg ? msg : "error");
    lua_settop(L, 0);
    return false;
  }
  lua_remove(L, fn);
  return true;
}

bool LoopFunctions::HasFunction(const char* name) {
  if (!L_) return false;
  bool has = RawGlobal(L_, name) == LUA_TFUNCTION;
  lua_pop(L_, 1);
  return has;
}

bool LoopFunctions::Call(const char* name, std::string* error) {
  if (!L_) return true;
  if (RawGlobal(L_, name) != LUA_TFUNCTION) {
    lua_pop(L_, 1);
    return true;
  }
  bool ok = PCall(0, 0, name, error);
  lua_settop(L_, 0);
  return ok;
}

bool LoopFunctions::FloorColor(double x, double y, Color* out, std::string* error) {
  lua_State* L = L_;
  RawGlobal(L, "floor_color");
  lua_pushnumber(L, x);
  lua_pushnumber(L, y);
  if (!PCall(2, 3, "floor_color", error)) return false;
  bool ok = true;
  if (lua_type(L, -3) == LUA_TSTRING) {
    auto c = ParseColor(lua_tostring(L, -3));
    if (c) *out = *c;
    else ok = false;
  } else if (lua_isnumber(L, -3) && lua_isnumber(L, -2) && lua_isnumber(L, -1)) {
    auto byte = [&](int i) { return static_cast<unsigned char>(std::clamp(lua_tonumber(L, i), 0.0, 255.0)); };
    *out = Color{byte(-3), byte(-2), byte(-1), 255};
  } else {
    ok = false;
  }
  lua_settop(L, 0);
  if (!ok) *error = "loop functions: floor_color(x, y) must return r, g, b (0-255) or a colour name";
  return ok;
}

bool LoopFunctions::IsExperimentFinished(bool* finished, std::string* error) {
  *finished = false;
  if (!L_) return true;
  if (RawGlobal(L_, "is_experiment_finished") != LUA_TFUNCTION) {
    lua_pop(L_, 1);
    return true;
  }
  if (!PCall(0, 1, "is_experiment_finished", error)) return false;
  *finished = lua_toboolean(L_, -1);
  lua_settop(L_, 0);
  return true;
}

bool LoopFunctions::PostExperiment(Json* metrics, bool* has_metrics, std::string* error) {
  *has_metrics = false;
  if (!L_) return true;
  if (RawGlobal(L_, "post_experiment") != LUA_TFUNCTION) {
    lua_pop(L_, 1);
    return true;
  }
  if (!PCall(0, 1, "post_experiment", error)) return false;
  if (lua_istable(L_, -1)) {
    std::string err;
    std::vector<std::string> nonfinite;
    if (!ToJson(L_, -1, metrics, 0, "", &nonfinite, &err)) {
      *error = "loop functions: post_experiment() result: " + err;
      lua_settop(L_, 0);
      return false;
    }
    *has_metrics = true;
    // One warning per run: metrics.json stays valid JSON, the user learns which keys were lost.
    if (!nonfinite.empty()) {
      log_ += "Eloop functions: warning: post_experiment() result: NaN or infinite number at ";
      for (size_t i = 0; i < nonfinite.size() && i < 5; ++i) log_ += (i ? ", " : "") + nonfinite[i];
      if (nonfinite.size() > 5) log_ += " and " + std::to_string(nonfinite.size() - 5) + " more";
      log_ += ", written as null in metrics.json\n";
    }
  }
  lua_settop(L_, 0);
  return true;
}

}  // namespace essaim
