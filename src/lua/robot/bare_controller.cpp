#include "lua/robot/bare_controller.h"

#include <lua.hpp>

#include "core/paths.h"
#include "core/rng.h"
#include "lua/host/lua_host.h"
#include "lua/robot/lua_devices.h"
#include "lua/robot/lua_math_types.h"
#include "lua/robot/lua_random.h"

namespace essaim {

namespace {
int NoOp(lua_State*) { return 0; }

/// Every function in robot.<device> (set_velocity, set_data, enable...) becomes a no-op:
/// the floor is the script's own work, not the actuators'. robot.random is kept.
void SilenceActuators(lua_State* L, int robot) {
  lua_pushnil(L);
  while (lua_next(L, robot)) {
    const bool is_random = lua_type(L, -2) == LUA_TSTRING && std::string(lua_tostring(L, -2)) == "random";
    if (lua_type(L, -1) == LUA_TTABLE && !is_random) {
      const int device = lua_gettop(L);
      lua_pushnil(L);
      while (lua_next(L, device)) {
        lua_pop(L, 1);
        lua_pushvalue(L, -1);
        if (lua_rawget(L, device) == LUA_TFUNCTION) {
          lua_pop(L, 1);
          lua_pushvalue(L, -1);
          lua_pushcfunction(L, NoOp);
          lua_rawset(L, device);  // assigning an existing key during lua_next is allowed
        } else {
          lua_pop(L, 1);
        }
      }
    }
    lua_pop(L, 1);
  }
}
}  // namespace

lua_State* BareController::NewState(BareAllocator allocator) {
  if (allocator == BareAllocator::Stock) return NewStockState();
  guard_ = std::make_unique<LuaGuard>();
  LuaOptions unlimited;  // the allocator alone: no memory cap, budget or wall clock
  unlimited.memory_limit = 0;
  unlimited.instruction_limit = unlimited.setup_instruction_limit = 0;
  unlimited.wall_seconds = 0;
  return NewGuardedState(guard_.get(), unlimited);
}

BareController::~BareController() {
  if (guard_)
    CloseGuardedState(guard_.get());
  else if (L_)
    lua_close(L_);
}

bool BareController::Load(const Model& model, const RobotDef& def, int index, uint64_t experiment_seed,
                          std::string* error, BareAllocator allocator) {
  def_ = &def;
  controller_ = &model.controllers[def.controller];
  scratch_.index = index;
  scratch_.controller_rng.Seed(DeriveSeed(experiment_seed, StreamKind::Controller, static_cast<uint64_t>(index)));
  scratch_.cmd.rab_data.assign(def.rab_data_size, 0);
  L_ = NewState(allocator);
  lua_State* L = L_;
  if (!L) {
    *error = "robot " + def.id + ": cannot create a Lua state";
    return false;
  }
  SetStateRobot(L, &scratch_);
  lua_gc(L, LUA_GCGEN, 0, 0);  // Lua's generational defaults; the run's own tuning is not the floor's
  luaL_openlibs(L);
  SeedMathRandom(L, DeriveSeed(experiment_seed, StreamKind::LuaMath, static_cast<uint64_t>(index)), index);
  for (const char* name : {"log", "logerr", "print"}) {
    lua_pushcfunction(L, NoOp);
    lua_setglobal(L, name);
  }
  OpenMathTypes(L);
  lua_newtable(L);
  const int robot = lua_gettop(L);
  lua_pushstring(L, def.id.c_str());
  lua_setfield(L, robot, "id");
  PushRobotRandomTable(L);
  lua_setfield(L, robot, "random");
  CreateDeviceTables(L, *controller_, def, &scratch_, &refs_);
  lua_settop(L, robot);
  SilenceActuators(L, robot);
  lua_newtable(L);
  for (const auto& kv : def.params) {
    lua_pushstring(L, kv.second.c_str());
    lua_setfield(L, -2, kv.first.c_str());
  }
  lua_setfield(L, robot, "params");
  lua_setglobal(L, "robot");

  const std::string& script = controller_->script;
  if (script.empty()) return true;
  PrependScriptFolder(L, script);
  lua_settop(L, 0);
  if (luaL_loadfile(L, script.c_str()) != LUA_OK || lua_pcall(L, 0, 0, 0) != LUA_OK) {
    *error = "robot " + def.id + ": " + lua_tostring(L, -1);
    lua_settop(L, 0);
    return false;
  }
  return true;
}

void BareController::PushReadings(const RobotState& robot) {
  if (L_) PushDeviceReadings(L_, *controller_, robot, &refs_);
}

bool BareController::Call(const char* fn, std::string* error) {
  lua_State* L = L_;
  if (!L || controller_->script.empty()) return true;
  if (lua_getglobal(L, fn) != LUA_TFUNCTION) {
    lua_settop(L, 0);
    if (std::string(fn) == "step") {
      *error = "robot " + def_->id + ": " + controller_->script + ": no global function 'step'";
      return false;
    }
    return true;
  }
  if (lua_pcall(L, 0, 0, 0) != LUA_OK) {
    *error = "robot " + def_->id + ": " + (lua_tostring(L, -1) ? lua_tostring(L, -1) : "error") + " (in " + fn + ")";
    lua_settop(L, 0);
    return false;
  }
  return true;
}

}  // namespace essaim
