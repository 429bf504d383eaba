// <controllers>: each kind of controller has a reader of its own (xml_lua_controller.cpp,
// xml_cpp_controller.cpp);
// here what every kind holds: an id used once, its devices checked against the device table, params.
#include <algorithm>
#include <string>
#include <vector>

#include "core/strings.h"
#include "model/device_params.h"
#include "model/xml_loader_impl.h"

namespace essaim::xml_loader {

void Loader::LoadControllers(const XMLElement* e) {
  ledger_.Visit(e);
  for (auto* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    const std::string tag = c->Name();
    if (tag == "lua_controller")
      LoadLuaController(c);
    else if (!c->Attribute("library") && !ClosestName(tag, {"lua_controller"}).empty())
      Error(c, "unknown controller type <" + tag + ">; did you mean <lua_controller>?");
    else
      LoadCppController(c);  // the tag is a REGISTER_CONTROLLER label
  }
}

// What every kind of controller holds, read after its id: no id used twice, <actuators>,
// <sensors> and <params> (each required, possibly empty), the devices, the params copied
// into `def`. Returns <params> (null when missing) for what the kind reads there.
const XMLElement* Loader::LoadControllerBody(const XMLElement* c, ControllerDef* def) {
  for (const ControllerDef& other : model_->controllers)
    if (other.id == def->id) Error(c, "duplicate controller id '" + def->id + "'");
  CheckChildren(c, {"actuators", "sensors", "params"}, "expected actuators, sensors, params");
  const XMLElement* act = c->FirstChildElement("actuators");
  const XMLElement* sen = c->FirstChildElement("sensors");
  const XMLElement* par = c->FirstChildElement("params");
  if (!act) Error(c, "missing required <actuators> (may be empty)");
  if (!sen) Error(c, "missing required <sensors> (may be empty)");
  if (!par) Error(c, "missing required <params> (may be empty)");
  if (act) LoadDevices(act, false, def);
  if (sen) LoadDevices(sen, true, def);
  if (par) {
    ledger_.ReadAll(par);  // free-form: the controller reads robot.params
    for (auto* a = par->FirstAttribute(); a; a = a->Next()) def->params[a->Name()] = a->Value();
  }
  return par;
}

// "unknown sensor", with the closest name of that kind, or where the name belongs.
static std::string UnknownDevice(const std::string& name, bool sensor) {
  const char* kind = sensor ? "sensor" : "actuator";
  if (FindDevice(name, !sensor))
    return std::string("'") + name + "' is " + (sensor ? "an actuator" : "a sensor") + ", not " +
           (sensor ? "a sensor" : "an actuator") + ": it goes inside <" + (sensor ? "actuators" : "sensors") + ">";
  std::vector<std::string> names;
  for (const DeviceRow& row : kDeviceRows)
    if (row.is_sensor == sensor) names.push_back(row.xml_name);
  std::string hint = ClosestName(name, names);
  return std::string("unknown ") + kind + (hint.empty() ? "" : "; did you mean <" + hint + ">?") +
         " (see `essaim devices`)";
}

void Loader::LoadDevices(const XMLElement* list, bool sensors, ControllerDef* c) {
  std::vector<DeviceConfig>& out = sensors ? c->sensors : c->actuators;
  ledger_.Visit(list);
  for (auto* d = list->FirstChildElement(); d; d = d->NextSiblingElement()) {
    const DeviceRow* row = FindDevice(d->Name(), sensors);
    if (!row) {
      Error(d, UnknownDevice(d->Name(), sensors));
      continue;
    }
    if (!row->supported) {
      Error(d, std::string(sensors ? "sensor" : "actuator") + " '" + d->Name() +
                   "' is an ARGoS device essaim does not support yet");
      continue;
    }
    DeviceConfig cfg;
    cfg.type = row->type;
    cfg.loc = Loc(d);
    cfg.implementation = Str(d, "implementation");
    if (cfg.implementation.empty())
      Error(d, "missing required attribute 'implementation'");
    else {
      std::vector<std::string> impls = Split(row->implementations, ',');
      if (std::find(impls.begin(), impls.end(), cfg.implementation) == impls.end())
        Error(d, "implementation '" + cfg.implementation + "' unknown; expected " + row->implementations);
    }
    // The device table's row is the schema: its attributes are the ones read (device_params).
    for (const DeviceAttr& da : row->attrs) ledger_.Read(d, da.name);
    for (auto* a = d->FirstAttribute(); a; a = a->Next()) cfg.attrs[a->Name()] = a->Value();
    for (const DeviceAttr& da : row->attrs)
      if (da.required && !Has(d, da.name)) Error(d, std::string("missing required attribute '") + da.name + "'");
    for (const DeviceConfig& prev : out)
      if (prev.type == cfg.type) Error(d, "device declared twice");
    ParseDeviceParams(&cfg, errors_);
    out.push_back(std::move(cfg));
  }
  // ARGoS applies devices in alphabetical tag order.
  std::stable_sort(out.begin(), out.end(), [](const DeviceConfig& a, const DeviceConfig& b) {
    return std::string(GetDeviceRow(a.type).xml_name) < GetDeviceRow(b.type).xml_name;
  });
}

}  // namespace essaim::xml_loader
