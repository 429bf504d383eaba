#include "argos/cpp_controller.h"

#include "argos/argos_session.h"
#include "argos/config_tree.h"
#include "model/device_table.h"

namespace essaim {

namespace {
// The .argos entry as the API library needs it: label, id, where, the devices declared.
ArgosControllerSpec SpecOf(const ControllerDef& c) {
  ArgosControllerSpec spec;
  spec.label = c.label;
  spec.config_id = c.id;
  spec.where = c.loc.file + ":" + std::to_string(c.loc.line) + ": <" + c.label + " id=\"" + c.id + "\">";
  for (const DeviceConfig& d : c.actuators)
    spec.devices.push_back({GetDeviceRow(d.type).xml_name, d.implementation, false});
  for (const DeviceConfig& d : c.sensors)
    spec.devices.push_back({GetDeviceRow(d.type).xml_name, d.implementation, true});
  return spec;
}

// The entry's <params>, as ARGoS hands it to Init (the loader requires one).
const XmlNode* ParamsOf(const ControllerDef& c) {
  for (const XmlNode& child : c.xml.children)
    if (child.name == "params") return &child;
  return nullptr;
}
}  // namespace

CppController::CppController(const Model& model, int index, RobotState* robot, ArgosHost* host)
    : model_(model), index_(static_cast<uint32_t>(index)), host_(*host), io_(robot) {}

std::unique_ptr<CppController> CppController::Make(const Model& model, int index, RobotState* robot, ArgosHost* host,
                                                   std::string* error) {
  std::unique_ptr<CppController> c(new CppController(model, index, robot, host));
  const RobotDef& def = model.robots[static_cast<size_t>(index)];
  const ControllerDef& entry = model.controllers[static_cast<size_t>(def.controller)];
  if (!host->Session().CreateController(c->index_, def.id, host->Libraries(), SpecOf(entry), &c->io_, error))
    return nullptr;
  return c;
}

CppController::~CppController() { host_.Session().DeleteController(index_); }

bool CppController::Init(std::string* error) {
  const ControllerDef& entry = model_.controllers[static_cast<size_t>(model_.robots[index_].controller)];
  const XmlNode* params = ParamsOf(entry);
  ticpp::Element tree = params ? ConfigurationTree(*params, entry.loc.file) : ticpp::Element("params");
  return host_.Session().InitController(index_, tree, error);
}

bool CppController::Step(std::string* error) { return host_.Session().StepController(index_, error); }
bool CppController::Destroy(std::string* error) { return host_.Session().DestroyController(index_, error); }
std::string& CppController::LogBuffer() { return host_.Session().ControllerLog(index_); }
bool CppController::LastErrorIsConfiguration() const { return host_.Session().LastErrorIsConfiguration(); }

// ARGoS's configuration helpers do not say what they read: every parameter counts as read.
void CppController::ParamReads(std::vector<std::string>* unread, std::vector<std::string>* read) const {
  unread->clear();
  read->clear();
}

}  // namespace essaim
