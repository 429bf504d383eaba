// One experiment's ARGoS side, made when its model names C++ loop functions or controllers:
// the experiment's libraries loaded as one group, the ArgosSession inside the API library
// (CSimulator, the space, the random categories), and the StoreWorld it sees the run through.
// The loop functions (cpp_loop_functions.h) and every robot's C++ controller (cpp_controller.h)
// live in this one session, as in ARGoS's one simulator: a controller reaches the loop
// functions' object, the loop functions reach the controllers.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "devices/entity_store.h"
#include "devices/robot_controller.h"
#include "model/model.h"

namespace essaim {

class ArgosSession;
class StoreWorld;

class ArgosHost {
 public:
  ArgosHost();
  ~ArgosHost();
  ArgosHost(const ArgosHost&) = delete;
  ArgosHost& operator=(const ArgosHost&) = delete;

  /// Whether `model` needs one (C++ loop functions or a C++ controller).
  static bool Needed(const Model& model);
  /// Loads the libraries, in ARGoS's order (ARGOS_PLUGIN_PATH's when a label comes without a
  /// library, then each <controllers> entry's, then the loop functions'), and makes the
  /// session. Everything passed must outlive it. False with `error`: bad input (exit 2).
  bool Load(const Model& model, EntityStore* entities, std::vector<std::unique_ptr<RobotController>>* controllers,
            std::string* error);
  bool Loaded() const { return session_ != nullptr; }
  void SetTick(uint64_t tick);
  ArgosSession& Session() { return *session_; }
  StoreWorld& World() { return *world_; }
  /// The loaded libraries' real paths, in load order (a label is looked up among these).
  const std::vector<std::string>& Libraries() const { return libraries_; }

 private:
  std::vector<std::string> libraries_;
  std::unique_ptr<StoreWorld> world_;
  std::unique_ptr<ArgosSession> session_;  // after world_: destroyed first
};

}  // namespace essaim
