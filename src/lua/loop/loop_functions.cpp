#include "lua/loop/loop_functions.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <lua.hpp>

#include "core/color.h"
#include "core/paths.h"
#include "core/strings.h"
#include "lua/lua_math_types.h"
#include "lua/lua_params.h"
#include "lua/lua_random.h"
#include "lua/lua_require.h"
#include "lua/loop/loop_handles.h"
#include "lua/loop/lua_to_value.h"

namespace essaim {

struct LoopFunctionsAccess {
  static LoopFunctions* Self(lua_State* L) { return LoopFunctionsOf(L); }
  static int RobotIndex(lua_State* L) {
    EntityHandle* h = ToEntityHandle(L, 1);
    if (!h || h->ref.kind != EntityKind::FootBot) luaL_typeerror(L, 1, "robot handle");
    return static_cast<int>(h->ref.serial);
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
  // r:lua_global / r:set_lua_global: CLuaController::GetLuaState(). The copy crosses
  // states through the tape; the controller's side runs under its own pcall, so a memory
  // error there stays there.
  struct CopyJob {
    LuaTape* tape;
    const char* name;
    const char* bad;
    bool ok;
  };
  static int CollectGlobal(lua_State* C) {
    auto* job = static_cast<CopyJob*>(lua_touserdata(C, 1));
    lua_rawgeti(C, LUA_REGISTRYINDEX, LUA_RIDX_GLOBALS);
    lua_pushstring(C, job->name);
    lua_rawget(C, -2);
    job->ok = job->tape->Record(C, -1, false, &job->bad);
    return 0;
  }
  static int StoreGlobal(lua_State* C) {
    auto* job = static_cast<CopyJob*>(lua_touserdata(C, 1));
    lua_rawgeti(C, LUA_REGISTRYINDEX, LUA_RIDX_GLOBALS);
    lua_pushstring(C, job->name);
    job->tape->Replay(C);
    lua_rawset(C, -3);
    job->ok = true;
    return 0;
  }
  static bool RunInController(lua_State* C, lua_CFunction fn, CopyJob* job) {
    if (!lua_checkstack(C, 3)) return false;
    const int top = lua_gettop(C);
    lua_pushcfunction(C, fn);
    lua_pushlightuserdata(C, job);
    const bool ok = lua_pcall(C, 1, 0, 0) == LUA_OK;
    lua_settop(C, top);
    return ok && job->ok;
  }
  static lua_State* ControllerState(LoopFunctions* lf, int i) {
    if (!lf->controllers_ || static_cast<size_t>(i) >= lf->controllers_->size()) return nullptr;
    return (*lf->controllers_)[i]->State();  // null: no script, or closed after its memory limit
  }
  static int LuaGlobal(lua_State* L) {
    LoopFunctions* lf = Self(L);
    const int i = RobotIndex(L);
    const char* name = luaL_checkstring(L, 2);
    lua_State* C = ControllerState(lf, i);
    if (!C) return lua_pushnil(L), 1;
    CopyJob job{&lf->tape_, name, nullptr, false};
    if (!RunInController(C, CollectGlobal, &job))
      return luaL_error(L, "lua_global: cannot copy '%s' from robot '%s': %s", name, lf->model_->robots[i].id.c_str(),
                        job.bad ? job.bad : "its Lua state is out of memory");
    lf->tape_.Replay(L);
    return 1;
  }
  static int SetLuaGlobal(lua_State* L) {
    LoopFunctions* lf = Self(L);
    const int i = RobotIndex(L);
    const char* name = luaL_checkstring(L, 2);
    luaL_checkany(L, 3);
    const char* bad = nullptr;
    if (!lf->tape_.Record(L, 3, true, &bad))
      return luaL_error(L, "set_lua_global: '%s' must be plain data (numbers, strings, booleans, tables): %s", name,
                        bad ? bad : "?");
    lua_State* C = ControllerState(lf, i);
    if (!C) return luaL_error(L, "set_lua_global: robot '%s' has no running controller", lf->model_->robots[i].id.c_str());
    CopyJob job{&lf->tape_, name, nullptr, false};
    if (!RunInController(C, StoreGlobal, &job))
      return luaL_error(L, "set_lua_global: robot '%s': its Lua state is out of memory", lf->model_->robots[i].id.c_str());
    return 0;
  }
  static int HandleIndex(lua_State* L) {
    EntityHandle* h = ToEntityHandle(L, 1);
    if (!h) luaL_typeerror(L, 1, "entity handle");
    const char* k = luaL_checkstring(L, 2);
    if (!std::strcmp(k, "id")) return lua_getiuservalue(L, 1, 1), 1;  // kept after removal, for messages
    if (!std::strcmp(k, "kind")) return lua_pushstring(L, EntityKindName(h->ref.kind)), 1;
    if (!std::strcmp(k, "index")) {
      if (h->ref.kind == EntityKind::FootBot) lua_pushinteger(L, static_cast<lua_Integer>(h->ref.serial) + 1);
      else lua_pushnil(L);
      return 1;
    }
    lua_getmetatable(L, 1);
    lua_pushvalue(L, 2);
    lua_rawget(L, -2);
    return 1;
  }
  // Two passes, so no Lua error unwinds through a C++ object (Debian's Lua longjmps, and a
  // half-appended row would be left behind): the first checks every item and leaves its
  // name and value on the stack; the second calls nothing that can raise and copies them.
  static int Timeseries(lua_State* L) {
    LoopFunctions* lf = Self(L);
    luaL_checktype(L, 1, LUA_TTABLE);
    const lua_Integer n = luaL_len(L, 1);
    const std::vector<std::string>& columns = lf->series_.columns;
    const bool first = columns.empty() && lf->series_.rows.empty();
    if (!first && static_cast<size_t>(n) != columns.size())
      return luaL_error(L, "timeseries: row has %d columns, the first row had %d", (int)n, (int)columns.size());
    if (n < 0 || n > 100000) return luaL_error(L, "timeseries: a row has 0 to 100000 columns, got %d", (int)n);
    luaL_checkstack(L, static_cast<int>(2 * n) + 3, "timeseries: too many columns");
    for (lua_Integer k = 1; k <= n; ++k) {
      lua_rawgeti(L, 1, k);
      if (!lua_istable(L, -1)) return luaL_error(L, "timeseries: each item must be {name, value}");
      lua_rawgeti(L, -1, 1);
      lua_rawgeti(L, -2, 2);
      size_t len = 0;
      const char* name = lua_isstring(L, -2) ? lua_tolstring(L, -2, &len) : nullptr;  // a number becomes text here
      if (!name || !lua_isnumber(L, -1)) return luaL_error(L, "timeseries: item %d must be {name, number}", (int)k);
      if (!first && (columns[k - 1].size() != len || std::memcmp(columns[k - 1].data(), name, len) != 0))
        return luaL_error(L, "timeseries: column %d is '%s', expected '%s'", (int)k, name, columns[k - 1].c_str());
      lua_remove(L, -3);  // the item; its name and value stay
    }
    const int base = lua_gettop(L) - static_cast<int>(2 * n);
    std::vector<double>& row = lf->series_.rows.emplace_back();
    row.reserve(static_cast<size_t>(n));
    int nonfinite = -1;
    for (int k = 0; k < n; ++k) {
      size_t len = 0;
      const char* name = lua_tolstring(L, base + 1 + 2 * k, &len);
      if (first) lf->series_.columns.emplace_back(name, len);  // whole, NUL bytes included
      row.push_back(lua_tonumber(L, base + 2 + 2 * k));
      if (nonfinite < 0 && !std::isfinite(row.back())) nonfinite = k;
    }
    if (nonfinite >= 0 && !lf->warned_nonfinite_row_) {
      lf->warned_nonfinite_row_ = true;
      std::string column = lf->series_.columns[static_cast<size_t>(nonfinite)];
      std::replace(column.begin(), column.end(), '\n', ' ');  // one log line
      lf->log_ += "Eloop functions: warning: timeseries(): NaN or infinite value in column '" + column +
                  "' at tick " + std::to_string(lf->tick_) +
                  ", written as NaN, Inf or -Inf in timeseries.csv (warned once per run)\n";
    }
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
    if (i > 1) *log += '\t';  // as print() and the controllers' log()
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

}  // namespace

LoopFunctions::~LoopFunctions() {
  CloseGuardedState(&guard_);
}

bool LoopFunctions::Load(const Model& model, std::vector<RobotState>* robots, PhysicsWorld* physics,
                         EntityStore* entities, std::vector<std::unique_ptr<LuaController>>* controllers,
                         const std::string& output_dir, std::string* error) {
  model_ = &model;
  robots_ = robots;
  physics_ = physics;
  entities_ = entities;
  controllers_ = controllers;
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
  RecordRequiredFiles(L, limits_.inputs);
  *static_cast<LoopFunctions**>(lua_getextraspace(L)) = this;  // LoopFunctionsOf
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
      {"battery", LoopFunctionsAccess::Battery},
      {"lua_global", LoopFunctionsAccess::LuaGlobal}, {"set_lua_global", LoopFunctionsAccess::SetLuaGlobal},
      {"set_battery", LoopFunctionsAccess::SetBattery}, {"alive", LoopFunctionsAccess::Alive},
      {"kill", LoopFunctionsAccess::Kill},         {"led", LoopFunctionsAccess::Led},
      {"controller_ok", LoopFunctionsAccess::ControllerOk}, {nullptr, nullptr}};
  lua_newtable(L);  // the robot-handle metatable
  luaL_setfuncs(L, handle_methods, 0);
  lua_pushcfunction(L, LoopFunctionsAccess::HandleIndex);
  lua_setfield(L, -2, "__index");
  handle_meta_ = lua_topointer(L, -1);  // kept alive by the registry
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
  for (const auto& child : model.loop_functions.children) {  // <params reset_all="true"/> → params.params.reset_all
    lua_newtable(L);
    for (const auto& kv : child.second) {
      lua_pushstring(L, kv.second.c_str());
      lua_setfield(L, -2, kv.first.c_str());
    }
    lua_setfield(L, -2, child.first.c_str());
  }
  PushTrackedParams(L, &params_);
  lua_setfield(L, -2, "params");
  lua_newtable(L);
  const std::pair<const char*, double> arena[] = {{"size_x", model.arena.size.x()}, {"size_y", model.arena.size.y()},
                                                  {"center_x", model.arena.center.x()}, {"center_y", model.arena.center.y()}};
  for (auto [k, v] : arena) {
    lua_pushnumber(L, v);
    lua_setfield(L, -2, k);
  }
  lua_setfield(L, -2, "arena");
  OpenEntityApi(L, -1);
  lua_createtable(L, static_cast<int>(robots->size()), 0);
  for (size_t i = 0; i < robots->size(); ++i) {
    PushEntityHandle(L, {EntityKind::FootBot, static_cast<uint32_t>(i)}, model.robots[i].id.c_str());
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
  SetRequireRoots(&guard_, {DirName(model.file), dir});
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

void LoopFunctions::ParamReads(std::vector<std::string>* unread, std::vector<std::string>* read) const {
  ListParamReads(L_, params_, unread, read);
}

void LoopFunctions::SetTick(uint64_t tick) {
  tick_ = tick;
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
    *error = "loop functions (" + std::string(what) + "): " + (!stopped.empty() ? (StopNamesItsLine(guard_) ? "" : script_ + ": ") + stopped : msg ? msg : "error");
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

bool LoopFunctions::PostExperiment(Value* metrics, bool* has_metrics, std::string* error) {
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
    if (!LuaToValue(L_, -1, metrics, &nonfinite, &err)) {
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
