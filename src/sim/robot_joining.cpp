#include "sim/robot_joining.h"

#include <memory>

#include "argos/cpp_controller.h"
#include "sim/error_groups.h"
#include "sim/world.h"

namespace essaim {

namespace {
// Its Lua state made and its script's top-level chunk run, or its C++ controller constructed.
std::unique_ptr<RobotController> MakeController(World& w, int index, std::string* error) {
  const RobotDef& def = w.model.robots[index];
  if (def.controller >= 0 && w.model.controllers[def.controller].Cpp())
    return CppController::Make(w.model, index, &w.robots[index], &w.argos, error);
  auto lua = std::make_unique<LuaController>();
  if (!lua->Load(w.model, def, &w.robots[index], w.model.experiment.seed, w.options.lua, error)) return nullptr;
  return lua;
}

// init() failed for a robot that runs on without its controller: recorded and printed
// as the errors of the robots made at the start.
void ReportInitError(World& w, int index, const std::string& message) {
  w.robots[index].controller_ok = false;
  const size_t before = w.controller_errors.size();
  w.controller_errors.push_back({w.model.robots[index].id, w.tick, message});
  if (w.options.log_sink)
    for (const std::string& text : GroupControllerErrors(w.controller_errors, before))
      w.options.log_sink('E', text, {w.tick, kLogHost});
}
}  // namespace

bool WorldRobotJoiner::Join(int index, std::string* error) {
  World& w = world_;
  const RobotDef& def = w.model.robots[index];
  const std::string& script = w.model.controllers[def.controller].script;
  if (!script.empty()) w.inputs->Add(script, "controller");
  std::unique_ptr<RobotController> controller = MakeController(w, index, error);
  if (!controller) return false;
  std::string init_error;
  const bool init_ok = controller->Init(&init_error);
  FlushLog(w, controller->LogBuffer(), index);
  if (!init_ok && (w.options.strict || controller->ExitCalled())) {
    *error = init_error;
    return false;
  }
  if (init_ok && !script.empty() && !controller->HasStep()) {
    *error = "robot " + def.id + ": " + script + ": no global function 'step' after init()";
    return false;
  }
  w.controllers.push_back(std::move(controller));
  w.pending_errors.emplace_back();
  w.chunk_times.emplace_back();
  if (!init_ok) ReportInitError(w, index, init_error);
  return true;
}

}  // namespace essaim
