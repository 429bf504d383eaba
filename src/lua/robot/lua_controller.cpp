#include "lua/robot/lua_controller.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <lua.hpp>

#include "core/paths.h"
#include "core/rng.h"
#include "core/strings.h"
#include "lua/host/compiled_scripts.h"
#include "lua/host/field_hint.h"
#include "lua/host/log_text.h"
#include "lua/host/lua_host.h"
#include "lua/host/lua_require.h"
#include "lua/host/stdout_lines.h"
#include "lua/robot/lua_devices.h"
#include "lua/robot/lua_math_types.h"
#include "lua/robot/lua_params.h"
#include "lua/robot/lua_random.h"

namespace essaim {

namespace {
// robot.<device> keys, each nil unless the controller declares the device: why, for the hint.
const std::vector<AbsentField>& DeviceFields() {
  static const std::vector<AbsentField> fields = [] {
    std::vector<AbsentField> out;
    for (const DeviceRow& row : kDeviceRows) {
      const std::string tag =
          std::string("<") + row.xml_name + "> in its " + (row.is_sensor ? "<sensors>" : "<actuators>");
      auto same = std::find_if(out.begin(), out.end(), [&](const AbsentField& f) { return f.name == row.lua_key; });
      if (same != out.end())
        same->why += " nor " + tag;
      else
        out.push_back(
            {row.lua_key, std::string("robot.") + row.lua_key + " is nil: this controller declares no " + tag});
    }
    return out;
  }();
  return fields;
}

int Traceback(lua_State* L) {
  const char* msg = lua_tostring(L, 1);
  if (!msg) {
    if (luaL_callmeta(L, 1, "__tostring") && lua_type(L, -1) == LUA_TSTRING) return 1;
    msg = lua_pushfstring(L, "(error object is a %s value)", luaL_typename(L, 1));
  } else {
    const std::string hint = FieldHint(L, msg, "robot", DeviceFields());
    if (!hint.empty()) msg = lua_pushfstring(L, "%s%s", msg, hint.c_str());
  }
  TellDebuggerRaised(L, msg ? msg : lua_tostring(L, 1));
  luaL_traceback(L, L, msg, 1);
  return 1;
}

int LogTo(lua_State* L, char stream) {
  auto* log = static_cast<std::string*>(lua_touserdata(L, lua_upvalueindex(1)));
  const size_t begin = log->size();
  *log += stream;
  AppendArgosLogText(L, log);
  EndLogEntry(log, begin);
  return 0;
}
int Log(lua_State* L) { return LogTo(L, 'O'); }
int LogErr(lua_State* L) { return LogTo(L, 'E'); }
}  // namespace

LuaController::~LuaController() { CloseGuardedState(&guard_); }

bool LuaController::Load(const Model& model, const RobotDef& def, RobotState* robot, uint64_t experiment_seed,
                         const LuaOptions& options, std::string* error) {
  robot_ = robot;
  robot_id_ = def.id;
  controller_ = &model.controllers[def.controller];
  guard_.name = "robot " + def.id;
  L_ = NewGuardedState(&guard_, options);
  if (!L_) {
    *error = "robot " + def.id + ": cannot create a Lua state";
    return false;
  }
  lua_State* L = L_;
  // Generational collection: the per-step values (positions, messages) die young, and the
  // incremental default lets them pile up to twice the live size before a cycle. A minor
  // collection after the heap grew by 50% (Lua's default: 20%) runs fewer atomic phases
  // (~8k instructions each) for the same frees; the major threshold goes to 300% so that
  // growth does not turn minors into majors. foraging-30 / -300: 1.5k / 1.0k fewer
  // instructions per robot-step. 100% saved a little more, but a state then outgrew
  // alloc_test's 60 KiB. The bare floor keeps Lua's defaults. A state's peak is its live
  // bytes times 1 + multiplier (the pool keeps it): at 1 000 avoidance robots 25 / 35 kept
  // it at 33.6 / 36.3 KB instead of 40.3, for 11 % / 4 % more CPU per robot-step.
  constexpr int kMinorMultiplier = 50, kMajorMultiplier = 300;
  // A state entering generational mode this empty takes its first majors for "bad" ones and
  // runs incremental cycles for a while, each started once the heap reached `pause` % of the
  // live bytes: Lua's 200 doubled a 33 KB state (avoidance.lua) to 66 KB. 150 bounds it lower
  // (with minors at 50 % the peak no longer depends on it: 100 and 110 peaked the same).
  constexpr int kPause = 150;
  lua_gc(L, LUA_GCINC, kPause, 0, 0);
  lua_gc(L, LUA_GCGEN, kMinorMultiplier, kMajorMultiplier);
  // What the host builds below is all kept: collecting while it grows from 5 to 25 KB
  // found nothing to free and cost ~4 µs a state. Back on before the script runs.
  lua_gc(L, LUA_GCSTOP);
  OpenGuardedLibraries(L, options.sandbox);
  RecordRequiredFiles(L, options.inputs);
  // Lua 5.4 seeds math.random from the clock: reseed from the experiment seed.
  SeedMathRandom(L, DeriveSeed(experiment_seed, StreamKind::LuaMath, robot->index), robot->index);
  lua_pushcfunction(L, Traceback);
  traceback_ref_ = luaL_ref(L, LUA_REGISTRYINDEX);
  OpenGlobals(L);
  CreateRobotTable(L, def, robot);
  if (!PushReadings(error)) return false;
  lua_gc(L, LUA_GCRESTART);

  const std::string& script = controller_->script;
  if (script.empty()) return true;  // the loader refuses it; a Model built in code may have none
  // model.dir: the .argos file's folder as essaim run made it absolute, whose folders its
  // working folder links (docs/loop-functions.md, "Files the loop functions write").
  SetRequireRoots(&guard_, {DirName(model.file), model.dir, DirName(script)});
  PrependScriptFolder(L, script);
  return RunChunk(options, error);
}

void LuaController::OpenGlobals(lua_State* L) {
  for (auto [name, fn] : {std::pair<const char*, lua_CFunction>{"log", Log}, {"logerr", LogErr}}) {
    lua_pushlightuserdata(L, &log_);
    lua_pushcclosure(L, fn, 1);
    lua_setglobal(L, name);
  }
  // print and io's writes to stdout: the buffer too, so output keeps robot order under threads.
  stdout_.log = &log_;
  RouteStdout(L, &stdout_);
  OpenMathTypes(L);
}

void LuaController::CreateRobotTable(lua_State* L, const RobotDef& def, RobotState* robot) {
  // id, random, params and the devices' tables: sized once, not rehashed as they come.
  lua_createtable(L, 0, 3 + static_cast<int>(controller_->actuators.size() + controller_->sensors.size()));
  lua_pushstring(L, def.id.c_str());
  lua_setfield(L, -2, "id");
  PushRandomTable(L, &robot->controller_rng);
  lua_setfield(L, -2, "random");
  CreateDeviceTables(L, *controller_, def, robot, &refs_);
  lua_newtable(L);
  for (const auto& kv : def.params) {
    lua_pushstring(L, kv.second.c_str());
    lua_setfield(L, -2, kv.first.c_str());
  }
  PushTrackedParams(L, &params_);
  lua_setfield(L, -2, "params");
  lua_setglobal(L, "robot");
}

bool LuaController::RunChunk(const LuaOptions& options, std::string* error) {
  lua_State* L = L_;
  const std::string& script = controller_->script;
  lua_rawgeti(L, LUA_REGISTRYINDEX, traceback_ref_);
  int base = lua_gettop(L);
  // The sandbox takes no bytecode from files: the script is read as text.
  const int loaded = options.scripts ? options.scripts->Load(L, script, options.sandbox)
                                     : luaL_loadfilex(L, script.c_str(), options.sandbox ? "t" : nullptr);
  if (loaded != LUA_OK) {
    *error = "robot " + robot_id_ + ": " + lua_tostring(L, -1);
    lua_settop(L, 0);
    return false;
  }
  BeginGuardedCall(&guard_, CallKind::Setup);
  const int status = lua_pcall(L, 0, 0, base);
  EndWrittenLine(&stdout_);
  std::string stopped = EndGuardedCall(&guard_, status);
  if (status != LUA_OK || !stopped.empty()) {
    *error = "robot " + robot_id_ + ": " +
             (stopped.empty() ? lua_tostring(L, -1) : (StopNamesItsLine(guard_) ? "" : script + ": ") + stopped);
    AddSandboxHint(guard_, error);
    lua_settop(L, 0);
    return false;
  }
  lua_settop(L, 0);
  return true;
}

namespace {
struct PushJob {
  const ControllerDef* controller;
  const RobotState* robot;
  LuaDeviceRefs* refs;
};

int PushProtected(lua_State* L) {
  const PushJob& job = *static_cast<const PushJob*>(lua_touserdata(L, 1));
  lua_pop(L, 1);
  PushDeviceReadings(L, *job.controller, *job.robot, job.refs);
  return 0;
}
}  // namespace

void LuaController::ParamReads(std::vector<std::string>* unread, std::vector<std::string>* read) const {
  ListParamReads(L_, params_, unread, read);
}

bool LuaController::PushReadings(std::string* error) {
  lua_State* L = L_;
  if (!L) return true;
  // Protected and guarded like a lifecycle call: fresh message tables allocate, so a state
  // at its memory limit raises here, and a controller's metamethod on a reading table
  // (lua_setfield honours __newindex) runs Lua code: either must stop this robot alone,
  // never abort or hang the process.
  PushJob job{controller_, robot_, &refs_};
  lua_pushcfunction(L, PushProtected);
  lua_pushlightuserdata(L, &job);
  BeginGuardedCall(&guard_, CallKind::Step);
  const int status = lua_pcall(L, 1, 0, 0);
  return Finish(status, "filling its sensor readings", "", error);
}

bool LuaController::HasFunction(const char* name) {
  if (!L_ || controller_->script.empty()) return false;
  const bool found = lua_getglobal(L_, name) == LUA_TFUNCTION;
  lua_pop(L_, 1);
  return found;
}

bool LuaController::Call(const char* fn, bool required, CallKind kind, std::string* error) {
  lua_State* L = L_;
  if (controller_->script.empty()) return true;
  if (!L) {
    *error = "robot " + robot_id_ + ": its Lua state was closed after an earlier error (in " + fn + ")";
    return false;
  }
  lua_rawgeti(L, LUA_REGISTRYINDEX, traceback_ref_);
  int base = lua_gettop(L);
  if (lua_getglobal(L, fn) != LUA_TFUNCTION) {
    lua_settop(L, 0);
    if (!required) return true;
    *error = "robot " + robot_id_ + ": " + controller_->script + ": no global function '" + fn + "'";
    return false;
  }
  BeginGuardedCall(&guard_, kind);
  const int status = lua_pcall(L, 0, 0, base);
  return Finish(status, "in ", fn, error);
}

bool LuaController::Finish(int status, const char* where, const char* name, std::string* error) {
  lua_State* L = L_;
  EndWrittenLine(&stdout_);
  std::string stopped = EndGuardedCall(&guard_, status);
  if (status != LUA_OK || !stopped.empty()) {
    const char* msg = lua_tostring(L, -1);
    // The limits name the script, unless their message names its line already.
    const std::string script = StopNamesItsLine(guard_) ? "" : controller_->script + ": ";
    *error = "robot " + robot_id_ + ": " +
             (!stopped.empty() ? script + stopped
              : msg            ? msg
                               : "error") +
             " (" + where + name + ")";
    AddSandboxHint(guard_, error);
    lua_settop(L, 0);
    if (guard_.memory_exceeded) {
      // Free what the runaway took; the robot never runs again.
      CloseGuardedState(&guard_);
      L_ = nullptr;
    }
    return false;
  }
  lua_settop(L, 0);
  return true;
}

}  // namespace essaim
