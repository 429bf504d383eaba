// Lua loop functions (docs/loop-functions.md): experiment logic in a script of its own
// state, reading and steering every robot through handles.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/value.h"
#include "devices/entity_store.h"
#include "devices/robot_state.h"
#include "lua/loop/lua_copy.h"
#include "lua/lua_guard.h"
#include "lua/lua_params.h"
#include "lua/lua_state.h"
#include "model/model.h"
#include "physics/physics_world.h"

struct lua_State;

namespace essaim {

struct EntityHandle;

struct Timeseries {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
};

class LoopFunctions {
 public:
  LoopFunctions() = default;
  ~LoopFunctions();
  LoopFunctions(const LoopFunctions&) = delete;
  LoopFunctions& operator=(const LoopFunctions&) = delete;

  /// Loads the script and runs its top-level chunk. Everything passed must outlive it;
  /// `controllers` may still be empty (filled before init()).
  bool Load(const Model& model, std::vector<RobotState>* robots, PhysicsWorld* physics, EntityStore* entities,
            std::vector<std::unique_ptr<LuaController>>* controllers, const std::string& output_dir,
            std::string* error);
  bool Loaded() const { return L_ != nullptr; }
  /// The watchdog's limits and the sandbox, as for controllers; set before Load.
  void SetLimits(const LuaOptions& options) { limits_ = options; }
  void SetTick(uint64_t tick);

  bool HasFunction(const char* name);
  /// floor_color(x, y) → colour; false with `error` on a Lua error or bad return.
  bool FloorColor(double x, double y, Color* out, std::string* error);
  bool Call(const char* name, std::string* error);  // init, pre_step, post_step, reset, destroy
  bool IsExperimentFinished(bool* finished, std::string* error);
  /// post_experiment(): the returned table as a value tree (`has_metrics` false when nil).
  bool PostExperiment(Value* metrics, bool* has_metrics, std::string* error);

  const Timeseries& Series() const { return series_; }
  const LuaGuard& Memory() const { return guard_; }
  std::string& LogBuffer() { return log_; }
  ::lua_State* State() { return L_; }
  /// experiment.params attributes never read so far, and the keys read.
  void ParamReads(std::vector<std::string>* unread, std::vector<std::string>* read) const;

 private:
  bool PCall(int nargs, int nresults, const char* what, std::string* error);
  lua_State* L_ = nullptr;
  LuaGuard guard_;
  LuaOptions limits_;
  std::string script_;
  int traceback_ref_ = -1;
  TrackedParams params_;     // experiment.params
  int experiment_ref_ = -1;  // `experiment`, held by the host: scripts may rebind the global
  std::string log_;
  Timeseries series_;
  bool warned_nonfinite_row_ = false;  // timeseries(): NaN/inf is warned about once per run
  uint64_t tick_ = 0;
  Rng rng_;
  // Context the robot handles reach through the registry.
  const Model* model_ = nullptr;
  std::vector<RobotState>* robots_ = nullptr;
  PhysicsWorld* physics_ = nullptr;
  EntityStore* entities_ = nullptr;
  std::vector<std::unique_ptr<LuaController>>* controllers_ = nullptr;
  // Scratch that Lua errors may unwind past without leaking: add_entity's spec, lua_global's
  // copy (C++ locals with destructors must not live across a Lua error).
  ObstacleDef obstacle_spec_;
  LightDef light_spec_;
  LuaTape tape_;
  const void* handle_meta_ = nullptr;  // the handle metatable, compared by address
  friend struct LoopFunctionsAccess;
  friend EntityHandle* ToEntityHandle(lua_State* L, int idx);
  friend struct LoopEntities;
};

}  // namespace essaim
