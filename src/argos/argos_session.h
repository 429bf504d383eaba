// One experiment's ARGoS side inside the ARGoS API library: the loop functions made from their
// label, the robots' C++ controllers made from theirs, the space of entity wrappers, the random
// generators. The host drives it call by call; each call runs with this session current
// (CSimulator::GetInstance), and a CARGoSException, or any exception, thrown comes back as `error`.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "argos/argos_robot_io.h"
#include "argos/argos_world.h"

namespace ticpp {
class Element;
}

namespace essaim {

enum class ArgosHook { Reset, Destroy, PreStep, PostStep, PostExperiment };

/// The labels registered so far by loaded libraries, each with the API version it was built
/// for and the library (real path) that registered it.
struct ArgosRegistration {
  std::string label;
  int api_version = 0;
  std::string library;
};
std::vector<ArgosRegistration> ArgosRegisteredLabels();
int ArgosApiVersion();
/// The labels REGISTER_CONTROLLER registered so far (as ArgosRegisteredLabels).
std::vector<ArgosRegistration> ArgosRegisteredControllers();
/// Appends to `into` the LOG/LOGERR lines written outside any hook since the last call
/// ("<O or E><text>\n" each) and forgets them.
void ArgosTakeOrphanLog(std::string* into);

/// A sensor or actuator a C++ controller declares (a child of its <sensors> or <actuators>).
struct ArgosDeviceDecl {
  std::string tag;             // "footbot_proximity", "differential_steering", ...
  std::string implementation;  // "default", "rot_z_only", "medium"
  bool sensor = true;
};

/// A C++ controller entry of the .argos file (<footbot_diffusion_controller id library>).
struct ArgosControllerSpec {
  std::string label;      // the element's tag: a REGISTER_CONTROLLER label
  std::string config_id;  // its id
  std::string where;      // "FILE:LINE: <LABEL id=\"ID\">", to name it in errors
  std::vector<ArgosDeviceDecl> devices;
};

class ArgosSession {
 public:
  explicit ArgosSession(ArgosWorld* world);
  ~ArgosSession();
  ArgosSession(const ArgosSession&) = delete;
  ArgosSession& operator=(const ArgosSession&) = delete;

  /// Makes the loop functions registered as `label` by one of `libraries` (real paths; the
  /// last that does, as ARGoS's factory); false with `error` when none does, one registers it
  /// twice, or it was built for another API version.
  bool Create(const std::vector<std::string>& libraries, const std::string& label, std::string* error);
  bool Init(ticpp::Element& tree, std::string* error);
  bool Run(ArgosHook hook, std::string* error);
  bool IsExperimentFinished(bool* finished, std::string* error);
  bool FloorColor(double x, double y, ArgosRgb* color, std::string* error);
  // ---- C++ controllers, one per robot index (robots added during the run included). Made,
  // inited, reset and destroyed one at a time in robot order; different robots' steps may run
  // at once on several threads. Each call runs with this session current and the robot's
  // controller as the target of LOG and LOGERR (ControllerLog).

  /// Makes robot `robot`'s controller from the label (the last of `libraries`, real paths in
  /// load order, that registers it, as ARGoS's factory), sets its id to `robot_id` (ARGoS's
  /// SetId(robot id)) and gives it one ARGoS sensor or actuator object per declared device,
  /// reading and commanding through `io` (which must outlive it). False with `error`: no
  /// library registers the label, another API version, a device the API has no class for,
  /// or the constructor threw.
  bool CreateController(uint32_t robot, const std::string& robot_id, const std::vector<std::string>& libraries,
                        const ArgosControllerSpec& spec, ArgosRobotIo* io, std::string* error);
  /// Init(<params>); false with `error` (the robot id, the file and line thrown from, the
  /// message; GetSensor of an undeclared device names the device and `spec.where`).
  bool InitController(uint32_t robot, ticpp::Element& params, std::string* error);
  /// Its sensors updated from `io` (those enabled), then ControlStep().
  bool StepController(uint32_t robot, std::string* error);
  bool ResetController(uint32_t robot, std::string* error);
  bool DestroyController(uint32_t robot, std::string* error);
  /// Deletes it (its destructor guarded; what it throws is dropped).
  void DeleteController(uint32_t robot);
  /// Lines LOG and LOGERR took while this robot's controller ran, "<O or E><text>\n" each
  /// (the host empties it in robot order).
  std::string& ControllerLog(uint32_t robot);

  /// Whether the last hook that failed threw a configuration error (a bad .argos element).
  bool LastErrorIsConfiguration() const;

  struct State;

 private:
  std::unique_ptr<State> state_;
};

}  // namespace essaim
