// The .argos loader's entry points and its order: Load reads each section in turn (the
// sections live in the xml_*.cpp files beside this one), then binds references across them.
#include "model/xml_loader.h"

#include <tinyxml2.h>

#include <chrono>
#include <memory>
#include <string>
#include <utility>

#include "core/hash.h"
#include "core/paths.h"
#include "core/rng.h"
#include "core/stopwatch.h"
#include "model/xml_loader_impl.h"
#include "model/xml_overrides.h"
#include "model/xml_syntax.h"

namespace essaim {
namespace xml_loader {

std::unique_ptr<Model> Loader::Load(const std::string& text) {
  model_ = std::make_unique<Model>();
  model_->file = path_;
  dir_ = DirName(path_);
  model_->dir = dir_;
  Fnv1a64 h;
  h.Add(text.data(), text.size());
  model_->file_hash = h.Hex();
  model_->overrides = options_.overrides;

  tinyxml2::XMLDocument doc;
  if (doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS) {
    errors_->Add(path_, doc.ErrorLineNum(), "", XmlSyntaxError(doc));
    return nullptr;
  }
  for (const std::string& o : options_.overrides) {
    std::string err;
    OverrideTarget target;
    if (!ApplyXmlOverride(doc, o, &err, &target))
      errors_->Add(path_, 0, "", err);
    else
      set_targets_.emplace_back(target, o);
  }
  XMLElement* root = doc.RootElement();
  if (!root) {
    errors_->Add(path_, 0, "", "empty document");
    return nullptr;
  }
  ledger_.ReadAll(root);  // ARGoS checks neither the root's name nor its attributes
  CheckChildren(root,
                {"framework", "controllers", "arena", "physics_engines", "media", "loop_functions", "visualization"},
                "expected framework, controllers, arena, physics_engines, media, loop_functions, visualization");
  auto required = [&](const char* name) -> XMLElement* {
    XMLElement* e = root->FirstChildElement(name);
    if (!e) errors_->Add(path_, root->GetLineNum(), root->Name(), std::string("missing required <") + name + ">");
    return e;
  };
  XMLElement* framework = required("framework");
  XMLElement* controllers = required("controllers");
  XMLElement* arena = required("arena");
  XMLElement* physics = required("physics_engines");
  XMLElement* media = required("media");
  if (framework) LoadFramework(framework);
  // The simulator's own stream places <distribute> entities.
  sim_rng_.Seed(DeriveSeed(model_->experiment.seed, StreamKind::Simulator, 0));
  if (controllers) LoadControllers(controllers);
  if (physics) LoadPhysics(physics);
  if (media) LoadMedia(media);
  if (XMLElement* lf = root->FirstChildElement("loop_functions")) LoadLoopFunctions(lf);
  if (root->FirstChildElement("visualization")) {
    XMLElement* vis = root->FirstChildElement("visualization");
    if (vis->FirstChildElement()) Warn(vis, "ignored: essaim is headless (see `essaim replay`)");
  }
  if (arena) LoadArena(arena);
  FinishPhysicsRegions();
  CheckReferences();
  ReportUnknownAttributes(root);
  if (!errors_->Empty()) return nullptr;
  return std::move(model_);
}

void Loader::CheckReferences() {
  // Bind each robot to its controller config now that all are known.
  for (RobotDef& r : model_->robots) {
    for (size_t i = 0; i < model_->controllers.size(); ++i)
      if (model_->controllers[i].id == r.controller_id) r.controller = static_cast<int>(i);
    if (r.controller < 0) {
      if (!r.controller_id.empty())
        errors_->Add(path_, r.controller_line, "controller", "no controller with id '" + r.controller_id + "'");
      continue;
    }
    const ControllerDef& c = model_->controllers[r.controller];
    if (r.params.count("__own__")) {
      r.params.erase("__own__");
    } else {
      r.params = c.params;
    }
  }
  auto check_medium = [&](const ControllerDef& c, DeviceType t, bool rab) {
    const DeviceConfig* d = c.Find(t);
    if (!d) return;
    std::string m = d->Attr("medium");
    bool found = false;
    if (rab)
      for (auto& x : model_->rab_media) found |= x.id == m;
    else
      for (auto& x : model_->led_media) found |= x.id == m;
    if (!found)
      errors_->Add(d->loc.file, d->loc.line, d->loc.element,
                   "medium '" + m + "' is not declared in <media> (<" + (rab ? "range_and_bearing" : "led") + " id=\"" +
                       m + "\"/>)");
  };
  for (const ControllerDef& c : model_->controllers) {
    check_medium(c, DeviceType::RabSensor, true);
    check_medium(c, DeviceType::LedsActuator, false);
    check_medium(c, DeviceType::CameraSensor, false);
    bool ground = c.Has(DeviceType::BaseGroundSensor) || c.Has(DeviceType::MotorGroundSensor);
    if (ground && model_->floor.source == FloorSource::None)
      errors_->Add(c.loc.file, c.loc.line, c.loc.element,
                   "ground sensors need a <floor> in the <arena> (ARGoS: \"No floor entity has been added\")");
  }
  if (model_->floor.source == FloorSource::LoopFunctions && model_->loop_functions.script.empty() &&
      !model_->loop_functions.Cpp())
    errors_->Add(model_->floor.loc.file, model_->floor.loc.line, "floor",
                 "source=\"loop_functions\" needs <loop_functions script=\"...\"> with floor_color(x, y) "
                 "(or C++ loop functions with GetFloorColor)");
}
}  // namespace xml_loader

std::string DeviceConfig::Attr(const std::string& name) const {
  auto it = attrs.find(name);
  if (it != attrs.end()) return it->second;
  for (const DeviceAttr& a : GetDeviceRow(type).attrs)
    if (name == a.name) return a.default_value;
  return "";
}

const DeviceConfig* ControllerDef::Find(DeviceType t) const {
  for (const DeviceConfig& d : actuators)
    if (d.type == t) return &d;
  for (const DeviceConfig& d : sensors)
    if (d.type == t) return &d;
  return nullptr;
}

std::unique_ptr<Model> LoadExperimentText(const std::string& xml, const std::string& path, const LoadOptions& options,
                                          ErrorList* errors, ErrorList* warnings) {
  const auto start = std::chrono::steady_clock::now();
  xml_loader::Loader loader(path, options, errors, warnings);
  std::unique_ptr<Model> model = loader.Load(xml);
  if (model) model->load_seconds.total = SecondsSince(start);
  return model;
}

std::unique_ptr<Model> LoadExperimentFile(const std::string& path, const LoadOptions& options, ErrorList* errors,
                                          ErrorList* warnings) {
  const auto start = std::chrono::steady_clock::now();
  std::string text;
  if (!ReadFile(path, &text)) {
    errors->Add(path, 0, "", "cannot read the experiment file");
    return nullptr;
  }
  std::unique_ptr<Model> model = LoadExperimentText(text, path, options, errors, warnings);
  if (model) model->load_seconds.total = SecondsSince(start);
  return model;
}

}  // namespace essaim
