#include "lua/loop/loop_functions.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <lua.hpp>

#include "core/color.h"
#include "core/paths.h"
#include "lua/host/field_hint.h"
#include "lua/host/log_text.h"
#include "lua/host/lua_require.h"
#include "lua/host/stdout_lines.h"
#include "lua/loop/loop_handles.h"
#include "lua/loop/lua_to_value.h"
#include "lua/robot/lua_math_types.h"
#include "lua/robot/lua_params.h"
#include "lua/robot/lua_random.h"

namespace essaim {

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
  if (msg) {
    const std::string hint = FieldHint(L, msg, "experiment");
    if (!hint.empty()) msg = lua_pushfstring(L, "%s%s", msg, hint.c_str());
  }
  TellDebuggerRaised(L, msg ? msg : lua_tostring(L, 1));
  luaL_traceback(L, L, msg ? msg : "(error object is not a string)", 1);
  return 1;
}

// log and logerr as a controller's (ARGoS's text).
int LoopLog(lua_State* L) {
  auto* log = static_cast<std::string*>(lua_touserdata(L, lua_upvalueindex(1)));
  const size_t begin = log->size();
  *log += static_cast<char>(lua_tointeger(L, lua_upvalueindex(2)));
  AppendArgosLogText(L, log);
  EndLogEntry(log, begin);
  return 0;
}

}  // namespace

LoopFunctions::~LoopFunctions() { CloseGuardedState(&guard_); }

void LoopFunctions::OpenLogs() {
  const std::pair<const char*, char> logs[] = {{"log", 'O'}, {"logerr", 'E'}};
  for (auto [name, stream] : logs) {
    lua_pushlightuserdata(L_, &context_.log);
    lua_pushinteger(L_, stream);
    lua_pushcclosure(L_, LoopLog, 2);
    lua_setglobal(L_, name);
  }
  // print as Lua's, and io's writes to stdout: the same buffer, in order with the robots'.
  stdout_.log = &context_.log;
  RouteStdout(L_, &stdout_);
}

// math.random seeded from the experiment, like the controllers'.
void LoopFunctions::SeedMathRandom(uint64_t seed) {
  const uint64_t s = DeriveSeed(seed, StreamKind::LoopFunctions, 1);
  lua_getglobal(L_, "math");
  lua_getfield(L_, -1, "randomseed");
  lua_pushinteger(L_, static_cast<lua_Integer>(s & 0x7fffffffffffffffull));
  lua_call(L_, 1, 0);
  lua_pop(L_, 1);
}

namespace {
// experiment.params: <loop_functions> attributes, and each child element as a table of its
// own (<params reset_all="true"/> gives params.params.reset_all).
void PushParamsTable(lua_State* L, const LoopFunctionsDef& def, TrackedParams* tracked) {
  lua_newtable(L);
  for (const auto& kv : def.params) {
    lua_pushstring(L, kv.second.c_str());
    lua_setfield(L, -2, kv.first.c_str());
  }
  for (const auto& child : def.children) {
    lua_newtable(L);
    for (const auto& kv : child.second) {
      lua_pushstring(L, kv.second.c_str());
      lua_setfield(L, -2, kv.first.c_str());
    }
    lua_setfield(L, -2, child.first.c_str());
  }
  PushTrackedParams(L, tracked);
}

void PushArenaTable(lua_State* L, const ArenaDef& arena) {
  lua_newtable(L);
  const std::pair<const char*, double> fields[] = {{"size_x", arena.size.x()},
                                                   {"size_y", arena.size.y()},
                                                   {"center_x", arena.center.x()},
                                                   {"center_y", arena.center.y()}};
  for (auto [k, v] : fields) {
    lua_pushnumber(L, v);
    lua_setfield(L, -2, k);
  }
}

void PushRobotHandles(lua_State* L, const Model& model) {
  lua_createtable(L, static_cast<int>(model.robots.size()), 0);
  for (size_t i = 0; i < model.robots.size(); ++i) {
    PushEntityHandle(L, {EntityKind::FootBot, static_cast<uint32_t>(i)}, model.robots[i].id.c_str());
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  lua_pushvalue(L, -1);
  lua_rawsetp(L, LUA_REGISTRYINDEX, &kRobotListKey);
}

// experiment.floor_changed(): the floor is sampled again before the robots next sense.
int MarkFloorChanged(lua_State* L) {
  LoopContextOf(L)->floor_changed = true;
  return 0;
}
}  // namespace

void LoopFunctions::PushExperiment(const Model& model, const std::string& output_dir) {
  lua_State* L = L_;
  lua_newtable(L);
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
  PushParamsTable(L, model.loop_functions, &params_);
  lua_setfield(L, -2, "params");
  PushArenaTable(L, model.arena);
  lua_setfield(L, -2, "arena");
  OpenEntityApi(L, -1);
  PushRobotHandles(L, model);
  lua_setfield(L, -2, "robots");
  rng_.Seed(DeriveSeed(model.experiment.seed, StreamKind::LoopFunctions, 0));
  PushRandomTable(L, &rng_);
  lua_setfield(L, -2, "random");
  lua_pushcfunction(L, AppendTimeseriesRow);
  lua_setfield(L, -2, "timeseries");
  lua_pushcfunction(L, MarkFloorChanged);
  lua_setfield(L, -2, "floor_changed");
}

bool LoopFunctions::TakeFloorChanged() {
  const bool changed = context_.floor_changed;
  context_.floor_changed = false;
  return changed;
}

// `require` finds modules next to the script first, and reads only below the .argos
// file's folder and the script's.
void LoopFunctions::SetPackagePath(const Model& model) {
  const std::string dir = DirName(context_.script);
  SetRequireRoots(&guard_, {DirName(model.file), model.dir, dir});  // model.dir: see LuaController
  lua_getglobal(L_, "package");
  lua_getfield(L_, -1, "path");
  std::string path = (dir.empty() ? std::string("./?.lua;") : dir + "/?.lua;") + lua_tostring(L_, -1);
  lua_pop(L_, 1);
  lua_pushstring(L_, path.c_str());
  lua_setfield(L_, -2, "path");
  lua_pop(L_, 1);
}

bool LoopFunctions::Load(const Model& model, EntityStore* entities,
                         std::vector<std::unique_ptr<RobotController>>* controllers, const std::string& output_dir,
                         std::string* error) {
  context_.model = &model;
  context_.entities = entities;
  context_.controllers = controllers;
  context_.script = model.loop_functions.script;
  if (context_.script.empty()) return true;
  guard_.name = "loop functions";
  L_ = NewGuardedState(&guard_, limits_);
  if (!L_) {
    *error = "loop functions: cannot create a Lua state";
    return false;
  }
  OpenGuardedLibraries(L_, limits_.sandbox);
  RecordRequiredFiles(L_, limits_.inputs);
  *static_cast<LoopContext**>(lua_getextraspace(L_)) = &context_;  // LoopContextOf
  lua_pushcfunction(L_, Traceback);
  traceback_ref_ = luaL_ref(L_, LUA_REGISTRYINDEX);
  OpenMathTypes(L_);
  OpenLogs();
  SeedMathRandom(model.experiment.seed);
  OpenRobotApi(L_);
  PushExperiment(model, output_dir);
  lua_pushvalue(L_, -1);
  experiment_ref_ = luaL_ref(L_, LUA_REGISTRYINDEX);
  lua_setglobal(L_, "experiment");
  SetPackagePath(model);
  if (luaL_loadfile(L_, context_.script.c_str()) != LUA_OK) {
    *error = "loop functions: " + std::string(lua_tostring(L_, -1));
    return false;
  }
  return PCall(0, 0, "top level", CallKind::Setup, error);
}

void LoopFunctions::ParamReads(std::vector<std::string>* unread, std::vector<std::string>* read) const {
  ListParamReads(L_, params_, unread, read);
}

void LoopFunctions::SetTick(uint64_t tick) {
  context_.tick = tick;
  if (!L_) return;
  // The host's own reference and a raw set, outside any pcall: no global a script rebinds
  // (`experiment = nil`) and no metamethod it adds can make this raise (a Lua panic).
  lua_rawgeti(L_, LUA_REGISTRYINDEX, experiment_ref_);
  lua_pushliteral(L_, "tick");
  lua_pushinteger(L_, static_cast<lua_Integer>(tick));
  lua_rawset(L_, -3);
  lua_pop(L_, 1);
}

bool LoopFunctions::PCall(int nargs, int nresults, const char* what, CallKind kind, std::string* error) {
  lua_State* L = L_;
  int fn = lua_gettop(L) - nargs;
  lua_rawgeti(L, LUA_REGISTRYINDEX, traceback_ref_);
  lua_insert(L, fn);
  BeginGuardedCall(&guard_, kind);
  const int status = lua_pcall(L, nargs, nresults, fn);
  EndWrittenLine(&stdout_);
  std::string stopped = EndGuardedCall(&guard_, status);
  if (status != LUA_OK || !stopped.empty()) {
    const char* msg = lua_tostring(L, -1);
    *error = "loop functions (" + std::string(what) + "): " +
             (!stopped.empty() ? (StopNamesItsLine(guard_) ? "" : context_.script + ": ") + stopped
              : msg            ? msg
                               : "error");
    AddSandboxHint(guard_, error);
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
  // The hooks that run every tick get the step budget; init, reset and destroy run once.
  const bool per_tick = std::strcmp(name, "pre_step") == 0 || std::strcmp(name, "post_step") == 0;
  bool ok = PCall(0, 0, name, per_tick ? CallKind::Step : CallKind::Setup, error);
  lua_settop(L_, 0);
  return ok;
}

bool LoopFunctions::FloorColor(double x, double y, Color* out, std::string* error) {
  lua_State* L = L_;
  RawGlobal(L, "floor_color");
  lua_pushnumber(L, x);
  lua_pushnumber(L, y);
  if (!PCall(2, 3, "floor_color", CallKind::Step, error)) return false;
  bool ok = true;
  if (lua_type(L, -3) == LUA_TSTRING) {
    auto c = ParseColor(lua_tostring(L, -3));
    if (c)
      *out = *c;
    else
      ok = false;
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
  if (!PCall(0, 1, "is_experiment_finished", CallKind::Step, error)) return false;
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
  if (!PCall(0, 1, "post_experiment", CallKind::Setup, error)) return false;
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
      context_.log += "Eloop functions: warning: post_experiment() result: NaN or infinite number at ";
      std::string& log = context_.log;
      for (size_t i = 0; i < nonfinite.size() && i < 5; ++i) log += (i ? ", " : "") + nonfinite[i];
      if (nonfinite.size() > 5) log += " and " + std::to_string(nonfinite.size() - 5) + " more";
      log += ", written as null in metrics.json\n";
    }
  }
  lua_settop(L_, 0);
  return true;
}

}  // namespace essaim
