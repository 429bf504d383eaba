// What steps a robot: its controller, a Lua script (lua/robot/lua_controller.h) or a C++ class
// built against ARGoS's control interface (argos/cpp_controller.h). It reads the robot's
// Readings and writes its Commands (robot_state.h); the World holds one per robot and calls
// it at ARGoS's points of the run: made, Init, then each tick Step, at the end Destroy.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace essaim {

/// Memory a controller holds (a Lua state's allocator; 0 for C++, whose heap is the process's).
struct ControllerMemory {
  size_t bytes = 0, peak = 0;
  size_t allocations = 0;  // (re)allocations so far: the no-churn tests read it
};

class RobotController {
 public:
  virtual ~RobotController() = default;
  /// Each false with `error` naming the robot, the file and line, the call: the robot stops.
  virtual bool Init(std::string* error) = 0;
  /// The readings its sensors took this tick handed over, then its step.
  virtual bool Step(std::string* error) = 0;
  virtual bool Destroy(std::string* error) = 0;
  /// Whether there is a step to call (a Lua script may define none).
  virtual bool HasStep() = 0;
  /// What it logged since the last take ("" if none), buffered so that robots stepped on
  /// several threads print in robot order.
  virtual std::string& LogBuffer() = 0;
  /// The controller ended the process's run (Lua's os.exit), not only its robot.
  virtual bool ExitCalled() const = 0;
  virtual ControllerMemory Memory() const = 0;
  /// Its parameters never read so far, and those read.
  virtual void ParamReads(std::vector<std::string>* unread, std::vector<std::string>* read) const = 0;
};

}  // namespace essaim
