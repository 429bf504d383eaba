// Robots' C++ controllers: REGISTER_CONTROLLER's registry, and the session's calls that make,
// init, step, reset, destroy and delete them. Each call runs with the session current and
// the robot's slot as this thread's call (LOG's target, CreateRNG's rule); what it throws
// comes back as "robot <id>: controller '<config id>' (<Hook>): <file>:<line>: <message>".
// Steps of different robots run at once: a step touches its own slot only, and allocates
// nothing once the readings are sized.
#include <argos3/core/control_interface/ci_controller.h>
#include <cxxabi.h>

#include <cstdlib>
#include <exception>

#include "argos/api/devices.h"
#include "argos/api/registry.h"
#include "argos/api/session_state.h"
#include "argos/argos_session.h"

namespace essaim {

namespace {
thread_local const ArgosControllerCall* current_call = nullptr;

ArgosRegistry<argos::TControllerCreator>& Registry() {
  static ArgosRegistry<argos::TControllerCreator> registry(
      {"controllers", "REGISTER_CONTROLLER", "the libraries its <controllers> elements name"});
  return registry;
}

std::string Prefix(const ArgosControllerSlot& slot, const char* hook) {
  return "robot " + slot.robot_id + ": controller '" + slot.config_id + "' (" + hook + "): ";
}

// Runs `body` as `slot`'s call with `state` current; an exception becomes `*error`. A call
// that may run beside other robots' (`parallel`) leaves the session's own fields alone.
template <typename Body>
bool Guarded(ArgosSession::State* state, ArgosControllerSlot& slot, const char* hook, bool parallel, Body&& body,
             std::string* error) {
  const ArgosControllerCall call{&slot, parallel};
  const ArgosControllerCall* call_before = current_call;
  ArgosSession::State* session_before = SetCurrentSession(state);
  current_call = &call;
  bool ok = false, configuration = false;
  try {
    body();
    ok = true;
  } catch (const argos::CARGoSException& e) {
    *error = Prefix(slot, hook) + DescribeException(e);
    configuration = e.IsConfigurationError();
  } catch (const std::exception& e) {
    *error = Prefix(slot, hook) + e.what();
  } catch (...) {
    *error = Prefix(slot, hook) + "an exception that is not a std::exception";
  }
  argos::LOG.Flush();  // this thread's lines, to the slot's log
  argos::LOGERR.Flush();
  current_call = call_before;
  SetCurrentSession(session_before);
  if (!parallel) state->configuration_error = configuration;
  return ok;
}

// The commands set so far handed to the robot (ARGoS's actuators' Update at the act stage).
void SendCommands(ArgosControllerSlot& slot) {
  for (auto& actuator : slot.actuators) actuator->Update();
}

std::string Demangled(const char* mangled) {
  int status = 0;
  char* name = abi::__cxa_demangle(mangled, nullptr, nullptr, &status);
  std::string out = status == 0 && name ? name : mangled;
  std::free(name);
  return out;
}
}  // namespace

const ArgosControllerCall* CurrentControllerCall() { return current_call; }

argos::CCI_Controller* CurrentController(uint32_t robot) {
  ArgosSession::State* session = CurrentSession();
  if (!session || robot >= session->controllers.size() || !session->controllers[robot]) return nullptr;
  return session->controllers[robot]->controller.get();
}

std::vector<ArgosRegistration> ArgosRegisteredControllers() { return Registry().List(); }

namespace {
// The slot of robot `robot`, or null with `error` when it has no controller.
ArgosControllerSlot* Slot(ArgosSession::State& state, uint32_t robot, std::string* error) {
  if (robot < state.controllers.size() && state.controllers[robot] && state.controllers[robot]->controller)
    return state.controllers[robot].get();
  *error = "robot " + std::to_string(robot) + " has no C++ controller";
  return nullptr;
}

// The controller and its devices, made in ARGoS's order: the controller, its id, then one
// object per declared actuator and sensor.
void Make(ArgosControllerSlot& slot, argos::TControllerCreator creator, const ArgosControllerSpec& spec,
          ArgosRobotIo* io) {
  slot.controller.reset(creator());
  slot.controller->SetId(slot.robot_id);
  for (const ArgosDeviceDecl& device : spec.devices)
    if (!device.sensor) AddDevice(device, io, spec.where, slot);
  for (const ArgosDeviceDecl& device : spec.devices)
    if (device.sensor) AddDevice(device, io, spec.where, slot);
}
}  // namespace

bool ArgosSession::CreateController(uint32_t robot, const std::string& robot_id,
                                    const std::vector<std::string>& libraries, const ArgosControllerSpec& spec,
                                    ArgosRobotIo* io, std::string* error) {
  const auto* found = Registry().Find(libraries, spec.label, error);
  if (!found) return false;
  if (found->api_version != ARGOS_ESSAIM_API_VERSION) {
    *error = "controller '" + spec.label + "' was built for essaim's ARGoS API version " +
             std::to_string(found->api_version) + ", this essaim provides version " +
             std::to_string(ARGOS_ESSAIM_API_VERSION) + ": rebuild the library against this essaim";
    return false;
  }
  if (robot >= state_->controllers.size()) state_->controllers.resize(robot + 1);
  if (state_->controllers[robot]) DeleteController(robot);  // made again (a placement retried)
  state_->controllers[robot] = std::make_unique<ArgosControllerSlot>();
  ArgosControllerSlot& slot = *state_->controllers[robot];
  slot.robot = robot, slot.robot_id = robot_id, slot.config_id = spec.config_id, slot.where = spec.where;
  if (Guarded(
          state_.get(), slot, "constructor", false, [&] { Make(slot, found->creator, spec, io); }, error))
    return true;
  const bool configuration = state_->configuration_error;  // an undeclarable device: a bad element
  DeleteController(robot);
  state_->configuration_error = configuration;
  return false;
}

bool ArgosSession::InitController(uint32_t robot, ticpp::Element& params, std::string* error) {
  ArgosControllerSlot* slot = Slot(*state_, robot, error);
  return slot && Guarded(
                     state_.get(), *slot, "Init", false,
                     [&] {
                       slot->controller->Init(params);
                       SendCommands(*slot);
                     },
                     error);
}

bool ArgosSession::StepController(uint32_t robot, std::string* error) {
  ArgosControllerSlot* slot = Slot(*state_, robot, error);
  return slot && Guarded(
                     state_.get(), *slot, "ControlStep", true,
                     [&] {
                       for (auto& sensor : slot->sensors) sensor->Update();
                       slot->controller->ControlStep();
                       SendCommands(*slot);
                     },
                     error);
}

// ARGoS's order: the sensors, the actuators, then the controller.
bool ArgosSession::ResetController(uint32_t robot, std::string* error) {
  ArgosControllerSlot* slot = Slot(*state_, robot, error);
  return slot && Guarded(
                     state_.get(), *slot, "Reset", false,
                     [&] {
                       for (auto& entry : slot->controller->GetAllSensors()) entry.second->Reset();
                       for (auto& entry : slot->controller->GetAllActuators()) entry.second->Reset();
                       slot->controller->Reset();
                       SendCommands(*slot);
                     },
                     error);
}

bool ArgosSession::DestroyController(uint32_t robot, std::string* error) {
  ArgosControllerSlot* slot = Slot(*state_, robot, error);
  return slot && Guarded(
                     state_.get(), *slot, "Destroy", false,
                     [&] {
                       for (auto& entry : slot->controller->GetAllSensors()) entry.second->Destroy();
                       for (auto& entry : slot->controller->GetAllActuators()) entry.second->Destroy();
                       slot->controller->Destroy();
                     },
                     error);
}

void ArgosSession::DeleteController(uint32_t robot) {
  if (robot >= state_->controllers.size() || !state_->controllers[robot]) return;
  ArgosControllerSlot& slot = *state_->controllers[robot];
  std::string ignored;
  Guarded(
      state_.get(), slot, "destructor", false, [&] { slot.controller.reset(); }, &ignored);
  // Its log stays for the host to take; the devices go with the controller.
  slot.sensors.clear();
  slot.actuators.clear();
}

std::string& ArgosSession::ControllerLog(uint32_t robot) {
  if (robot < state_->controllers.size() && state_->controllers[robot]) return state_->controllers[robot]->log;
  state_->no_log.clear();
  return state_->no_log;
}

}  // namespace essaim

namespace argos {

bool RegisterController(const char* str_label, TControllerCreator pf_creator, int n_api_version) {
  essaim::Registry().Add(str_label, pf_creator, n_api_version);
  return true;
}

// A message without a source file: the .argos element it names is where to look.
void CCI_Controller::ThrowUnknownDevice(bool b_sensor, const std::string& str_type) {
  const essaim::ArgosControllerCall* call = essaim::CurrentControllerCall();
  const std::string where = call ? " (" + call->slot->where + ")" : "";
  // A configuration error: the .argos entry lacks the device (bad input, exit 2).
  throw CARGoSException::Configuration(std::string("Unknown ") + (b_sensor ? "sensor" : "actuator") + " type " +
                                       str_type + " requested in controller" + where +
                                       ". Did you add it to the XML file?");
}

// Names the class the declared implementation made, which tells which implementation to declare.
void CCI_Controller::ThrowBadCast(bool b_sensor, const std::string& str_type, const char* str_wanted,
                                  const char* str_made) {
  const essaim::ArgosControllerCall* call = essaim::CurrentControllerCall();
  const std::string where = call ? " (" + call->slot->where + ")" : "";
  throw CARGoSException(std::string(b_sensor ? "Sensor" : "Actuator") + " type " + str_type + where +
                        " cannot be cast to type " + essaim::Demangled(str_wanted) + ": its implementation made a " +
                        essaim::Demangled(str_made));
}

}  // namespace argos
