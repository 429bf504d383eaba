// A robot's C++ controller (docs/cpp-controllers.md): a class of a library built against
// essaim's ARGoS API, registered with REGISTER_CONTROLLER, made in the experiment's ArgosSession
// with one ARGoS sensor or actuator object per device its .argos entry declares, each reading
// and commanding the robot through a RobotIo over its RobotState.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "argos/argos_host.h"
#include "argos/robot_io.h"
#include "devices/robot_controller.h"
#include "devices/robot_state.h"
#include "model/model.h"

namespace essaim {

class CppController : public RobotController {
 public:
  /// Robot `index`'s controller, made (constructed, id set, devices given) in `host`'s session.
  /// Null with `error` when the label is registered by none of the experiment's libraries, or
  /// the constructor throws. `host` and `robot` must outlive it.
  static std::unique_ptr<CppController> Make(const Model& model, int index, RobotState* robot, ArgosHost* host,
                                             std::string* error);
  ~CppController() override;

  bool Init(std::string* error) override;
  bool Step(std::string* error) override;
  bool Destroy(std::string* error) override;
  bool HasStep() override { return true; }
  std::string& LogBuffer() override;
  bool ExitCalled() const override { return false; }
  ControllerMemory Memory() const override { return {}; }
  void ParamReads(std::vector<std::string>* unread, std::vector<std::string>* read) const override;
  /// Whether the last call that failed threw a configuration error (a bad <params>, GetSensor
  /// of an undeclared device): bad input.
  bool LastErrorIsConfiguration() const;

 private:
  CppController(const Model& model, int index, RobotState* robot, ArgosHost* host);

  const Model& model_;
  uint32_t index_;
  ArgosHost& host_;
  RobotIo io_;
};

}  // namespace essaim
