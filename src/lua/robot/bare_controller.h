// A controller script in a bare lua_State, fed readings from outside: the floor of a run's
// cost. The same robot table layout as LuaController, but the actuators are
// no-ops, log/print discard, there is no watchdog, and the readings are pushed by the
// caller before the timed step() call, so that timing step() measures the script alone.
#pragma once
#include <memory>
#include <string>

#include "devices/robot_state.h"
#include "lua/robot/lua_device_refs.h"
#include "model/model.h"

struct lua_State;

namespace essaim {

struct LuaGuard;

/// Which allocator the bare state runs on. Stock: Lua's own (malloc), i.e. "bare Lua 5.4"
/// as the floor is defined. Pool: the run's controllers' allocator (lua_guard's
/// small-block pool and accounting, no limits), so that a run/floor ratio compares the same
/// Lua runtime and measures only what the simulator adds.
enum class BareAllocator { Stock, Pool };

class BareController {
 public:
  BareController() = default;
  ~BareController();
  BareController(const BareController&) = delete;
  BareController& operator=(const BareController&) = delete;

  /// Builds the state (robot.random seeded as the real run's robot `index`) and runs the
  /// script's top-level chunk. False with `error` naming the robot and script.
  bool Load(const Model& model, const RobotDef& def, int index, uint64_t experiment_seed, std::string* error,
            BareAllocator allocator = BareAllocator::Stock);
  /// Copies `robot`'s readings into this state's robot.* tables (not timed by the caller).
  void PushReadings(const RobotState& robot);
  /// init() / step(); false with `error` when the script raised one.
  bool CallInit(std::string* error) { return Call("init", error); }
  bool CallStep(std::string* error) { return Call("step", error); }
  ::lua_State* State() { return L_; }

 private:
  bool Call(const char* fn, std::string* error);
  lua_State* NewState(BareAllocator allocator);

  lua_State* L_ = nullptr;
  std::unique_ptr<LuaGuard> guard_;  // BareAllocator::Pool only
  const RobotDef* def_ = nullptr;
  const ControllerDef* controller_ = nullptr;
  RobotState scratch_;  // what the (replaced) actuator closures were created over
  LuaDeviceRefs refs_;
};

}  // namespace essaim
