// Lua loop functions (docs/loop-functions.md): experiment logic in a script of its own
// state, reading and steering every robot through handles.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/value.h"
#include "devices/entity_store.h"
#include "lua/host/lua_guard.h"
#include "lua/host/stdout_lines.h"
#include "lua/loop/loop_context.h"
#include "lua/robot/lua_controller.h"
#include "lua/robot/lua_params.h"
#include "model/model.h"

struct lua_State;

namespace essaim {

class LoopFunctions {
 public:
  LoopFunctions() = default;
  ~LoopFunctions();
  LoopFunctions(const LoopFunctions&) = delete;
  LoopFunctions& operator=(const LoopFunctions&) = delete;

  /// Loads the script and runs its top-level chunk. Everything passed must outlive it;
  /// `controllers` may still be empty (filled before init()). Scripts reach the World only
  /// through `entities`.
  bool Load(const Model& model, EntityStore* entities, std::vector<std::unique_ptr<RobotController>>* controllers,
            const std::string& output_dir, std::string* error);
  bool Loaded() const { return L_ != nullptr; }
  /// The watchdog's limits and the sandbox, as for controllers; set before Load.
  void SetLimits(const LuaOptions& options) { limits_ = options; }
  void SetTick(uint64_t tick);

  bool HasFunction(const char* name);
  /// floor_color(x, y) → colour; false with `error` on a Lua error or bad return.
  bool FloorColor(double x, double y, Color* out, std::string* error);
  /// Whether experiment.floor_changed() was called since the last call (ARGoS's
  /// GetFloorEntity().SetChanged()): the floor is then sampled again.
  bool TakeFloorChanged();
  bool Call(const char* name, std::string* error);  // init, pre_step, post_step, reset, destroy
  bool IsExperimentFinished(bool* finished, std::string* error);
  /// post_experiment(): the returned table as a value tree (`has_metrics` false when nil).
  bool PostExperiment(Value* metrics, bool* has_metrics, std::string* error);

  const Timeseries& Series() const { return context_.series; }
  const LuaGuard& Memory() const { return guard_; }
  std::string& LogBuffer() { return context_.log; }
  ::lua_State* State() { return L_; }
  /// experiment.params attributes never read so far, and the keys read.
  void ParamReads(std::vector<std::string>* unread, std::vector<std::string>* read) const;

 private:
  bool PCall(int nargs, int nresults, const char* what, CallKind kind, std::string* error);
  void OpenLogs();
  void SeedMathRandom(uint64_t seed);
  /// The `experiment` table, left on the stack.
  void PushExperiment(const Model& model, const std::string& output_dir);
  void SetPackagePath(const Model& model);
  lua_State* L_ = nullptr;
  LuaGuard guard_;
  LuaOptions limits_;
  int traceback_ref_ = -1;
  TrackedParams params_;     // experiment.params
  int experiment_ref_ = -1;  // `experiment`, held by the host: scripts may rebind the global
  Rng rng_;
  LoopContext context_;  // what the bindings reach (LoopContextOf)
  WrittenLines stdout_;  // print's and io.write's lines into context_.log, and the open one
};

}  // namespace essaim
