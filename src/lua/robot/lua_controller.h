// One robot's Lua controller: its own lua_State, the `robot` table, and the ARGoS
// lifecycle (init, step, reset, destroy). The only place besides loop_functions that
// touches the Lua C API for controllers.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "devices/robot_controller.h"
#include "devices/robot_state.h"
#include "lua/host/lua_guard.h"
#include "lua/host/stdout_lines.h"
#include "lua/robot/lua_device_refs.h"
#include "lua/robot/lua_params.h"
#include "model/model.h"

struct lua_State;

namespace essaim {

class LuaController : public RobotController {
 public:
  LuaController() = default;
  ~LuaController() override;
  // Lua keeps a pointer to guard_ and closures keep `this`: never copied or moved.
  LuaController(const LuaController&) = delete;
  LuaController& operator=(const LuaController&) = delete;

  /// Builds the state and the robot table and runs the script's top-level chunk
  /// (not init). On failure returns false with `error` naming the script and line.
  bool Load(const Model& model, const RobotDef& def, RobotState* robot, uint64_t experiment_seed,
            const LuaOptions& options, std::string* error);
  /// Copies the robot's Readings into its Lua tables, as a guarded call: false with `error`
  /// (robot id, the limit hit) if it fails, the state closed as by a lifecycle call.
  bool PushReadings(std::string* error);
  /// Call a lifecycle function; false with `error` (robot id, file:line, traceback).
  /// A state that hit its memory limit is closed and its memory freed.
  bool CallInit(std::string* error) { return Call("init", false, CallKind::Setup, error); }
  bool CallStep(std::string* error) { return Call("step", true, CallKind::Step, error); }
  bool CallDestroy(std::string* error) { return Call("destroy", false, CallKind::Setup, error); }
  // RobotController: init(), PushReadings then step(), destroy().
  bool Init(std::string* error) override { return CallInit(error); }
  bool Step(std::string* error) override { return PushReadings(error) && CallStep(error); }
  bool Destroy(std::string* error) override { return CallDestroy(error); }
  bool HasStep() override { return HasFunction("step"); }
  /// The script defines global function `name` (false without a script or a state).
  bool HasFunction(const char* name);

  /// log()/logerr() output since the last take, in call order ("" if none). Buffered so
  /// robots stepped on several threads still print in robot order.
  std::string& LogBuffer() override { return log_; }
  const LuaGuard& Guard() const { return guard_; }
  ControllerMemory Memory() const override { return {guard_.bytes, guard_.peak, guard_.allocations}; }
  /// robot.params keys never read so far and those read (nothing once the state is closed).
  void ParamReads(std::vector<std::string>* unread, std::vector<std::string>* read) const override;
  /// The script called os.exit: the run ends (as an error), not just this robot.
  bool ExitCalled() const override { return !guard_.exit_called.empty(); }
  ::lua_State* State() { return L_; }

 private:
  bool Call(const char* fn, bool required, CallKind kind, std::string* error);
  /// The globals every controller script sees: log, logerr, print (and io's writes to
  /// stdout) into the log buffer, vector types.
  void OpenGlobals(::lua_State* L);
  /// The robot table, in ARGoS's order: id, random, actuators, sensors, params.
  void CreateRobotTable(::lua_State* L, const RobotDef& def, RobotState* robot);
  /// Runs the script's top-level chunk, guarded; false with `error`.
  bool RunChunk(const LuaOptions& options, std::string* error);
  /// After a guarded pcall: the error (robot id, what stopped it, `where`) and the state
  /// closed if it ran out of memory; true if the call went through. The error ends with
  /// " (" where name ")", e.g. " (in step)".
  bool Finish(int status, const char* where, const char* name, std::string* error);

  ::lua_State* L_ = nullptr;
  LuaGuard guard_;
  RobotState* robot_ = nullptr;  // a RobotStates element: it stays put while robots join
  std::string robot_id_;         // not the RobotDef: the scene's list grows during a run
  const ControllerDef* controller_ = nullptr;
  std::string log_;
  WrittenLines stdout_;  // print's and io.write's lines into log_, and the open one
  int traceback_ref_ = -1;
  LuaDeviceRefs refs_;    // device tables refreshed each tick
  TrackedParams params_;  // robot.params
};

/// The Lua state of a robot's controller; null for a C++ controller, or a Lua one with no state.
inline ::lua_State* LuaStateOf(RobotController* c) {
  auto* lua = dynamic_cast<LuaController*>(c);
  return lua ? lua->State() : nullptr;
}

}  // namespace essaim
