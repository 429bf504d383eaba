// The .argos loader's entry points and its order: Load reads each section in turn (the
// sections live in the xml_*.cpp files beside this one), then binds references across them.
#include "model/xml_loader.h"

#include <tinyxml2.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>

#include "core/color.h"
#include "core/hash.h"
#include "core/paths.h"
#include "core/rng.h"
#include "core/stopwatch.h"
#include "core/strings.h"
#include "model/attribute_ledger.h"
#include "model/distribute.h"
#include "model/floor_image.h"
#include "model/limits.h"
#include "model/physics_regions.h"
#include "model/placement.h"
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

// Whether `more` entities (foot-bots when `robots`) fit beside those loaded so far.
bool Loader::RoomFor(const XMLElement* e, long long more, bool robots) {
  EntityCounts counts{static_cast<double>(model_->robots.size()),
                      static_cast<double>(model_->obstacles.size() + model_->lights.size())};
  (robots ? counts.robots : counts.objects) += static_cast<double>(more);
  std::string problem = EntityCountProblem(counts, model_->experiment.limits);
  if (problem.empty()) return true;
  Error(e, problem);
  return false;
}

void Loader::LoadControllers(const XMLElement* e) {
  ledger_.Visit(e);
  for (auto* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    if (std::string(c->Name()) != "lua_controller") {
      Error(c, "unsupported controller type: essaim runs Lua controllers (<lua_controller>)");
      continue;
    }
    ControllerDef def;
    def.id = Required(c, "id");
    def.loc = Loc(c);
    if (Has(c, "library")) Warn(c, "attribute 'library' ignored for a Lua controller");
    for (const ControllerDef& other : model_->controllers)
      if (other.id == def.id) Error(c, "duplicate controller id '" + def.id + "'");
    CheckChildren(c, {"actuators", "sensors", "params"}, "expected actuators, sensors, params");
    const XMLElement* act = c->FirstChildElement("actuators");
    const XMLElement* sen = c->FirstChildElement("sensors");
    const XMLElement* par = c->FirstChildElement("params");
    if (!act) Error(c, "missing required <actuators> (may be empty)");
    if (!sen) Error(c, "missing required <sensors> (may be empty)");
    if (!par) Error(c, "missing required <params> (may be empty)");
    if (act) LoadDevices(act, false, &def);
    if (sen) LoadDevices(sen, true, &def);
    if (par) {
      ledger_.ReadAll(par);  // free-form: the controller reads robot.params
      for (auto* a = par->FirstAttribute(); a; a = a->Next()) def.params[a->Name()] = a->Value();
      std::string script = Str(par, "script");
      if (!script.empty()) {
        def.script = ResolvePath(script);
        if (!FileExists(def.script))
          Error(par, "script '" + script + "' not found (looked beside the .argos file and in the working directory)");
      } else {
        // ARGoS loads no script and its robots stand still in silence: never what was meant.
        Error(c, "lua_controller '" + def.id + "' has no script: add <params script=\"file.lua\"/>");
      }
    }
    model_->controllers.push_back(std::move(def));
  }
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

void Loader::LoadBody(const XMLElement* body, Pose2* pose, double* z) {
  Vec3 p = Vector3(body, "position", Vec3::Zero());
  Vec3 o = Vector3(body, "orientation", Vec3::Zero());
  pose->x = p.x();
  pose->y = p.y();
  *z = p.z();
  pose->yaw = YawFromDegrees(o.x());
  if (o.y() != 0 || o.z() != 0) Warn(body, "pitch and roll ignored: essaim is planar");
  Placeable(body, p);
}

bool Loader::LoadFootBot(const XMLElement* e, RobotDef* r) {
  size_t before = errors_->Size();
  r->id = Required(e, "id");
  r->loc = Loc(e);
  r->rab_range = Double(e, "rab_range", 3.0);
  long long rab_data_size = Int(e, "rab_data_size", 10);
  if (r->rab_range < 0) Error(e, "rab_range must be >= 0");
  // Checked before the cast to int: a huge value used to wrap into range.
  if (rab_data_size < 0 || rab_data_size > 65536)
    Error(e, "rab_data_size out of range");
  else
    r->rab_data_size = static_cast<int>(rab_data_size);
  r->camera_aperture = DegToRad(Double(e, "omnidirectional_camera_aperture", 70));
  CheckChildren(e, {"body", "controller", "battery", "dynamics2d"}, "expected body, controller, battery, dynamics2d");
  if (const XMLElement* body = e->FirstChildElement("body")) LoadBody(body, &r->pose, &r->z);
  const XMLElement* ctrl = e->FirstChildElement("controller");
  if (!ctrl) {
    Error(e, "missing required <controller config=\"...\"/>");
  } else {
    r->controller_id = Required(ctrl, "config");
    r->controller_line = ctrl->GetLineNum();
    if (const XMLElement* params = ctrl->FirstChildElement("params")) {
      // Per-robot <params> replaces the controller's entirely (spec quirk 15).
      r->params.clear();
      r->params["__own__"] = "";
      ledger_.ReadAll(params);
      for (auto* a = params->FirstAttribute(); a; a = a->Next()) r->params[a->Name()] = a->Value();
    }
  }
  if (const XMLElement* b = e->FirstChildElement("battery")) {
    BatteryDef& bd = r->battery;
    std::string m = Str(b, "discharge_model", "time");
    if (m == "time")
      bd.model = DischargeModel::Time;
    else if (m == "motion")
      bd.model = DischargeModel::Motion;
    else if (m == "time_motion")
      bd.model = DischargeModel::TimeMotion;
    else
      Error(b, "discharge_model must be time, motion or time_motion");
    if (Has(b, "model")) Warn(b, "attribute 'model' is not read by ARGoS either; use discharge_model");
    bd.start_charge = Double(b, "start_charge", 1.0);
    bd.full_charge = Double(b, "full_charge", 1.0);
    bd.delta = Double(b, "delta", 1e-5);
    bd.pos_delta = Double(b, "pos_delta", 1e-3);
    bd.orient_delta = Double(b, "orient_delta", 1e-3);
    bd.time_factor = Double(b, "time_factor", 1e-5);
    bd.pos_factor = Double(b, "pos_factor", 1e-3);
    bd.orient_factor = Double(b, "orient_factor", 1e-3);
    if (bd.full_charge <= 0) Error(b, "full_charge must be > 0");
  }
  if (const XMLElement* d = e->FirstChildElement("dynamics2d")) {
    CheckChildren(d, {"differential_steering"}, "expected differential_steering");
    if (const XMLElement* ds = d->FirstChildElement("differential_steering")) {
      r->max_force = Double(ds, "max_force", footbot::kMaxForce);
      r->max_torque = Double(ds, "max_torque", footbot::kMaxTorque);
    }
  }
  return errors_->Size() == before;
}

bool Loader::LoadObstacle(const XMLElement* e, ObstacleDef* o, bool needs_body) {
  size_t before = errors_->Size();
  std::string tag = e->Name();
  o->kind = tag == "box" ? ShapeKind::Box : ShapeKind::Cylinder;
  o->id = Required(e, "id");
  o->loc = Loc(e);
  if (o->kind == ShapeKind::Box) {
    Vec3 s = Vector3(e, "size", Vec3::Zero(), true);
    o->size_x = s.x(), o->size_y = s.y(), o->height = s.z();
    if (s.x() <= 0 || s.y() <= 0 || s.z() <= 0) Error(e, "size components must be > 0");
  } else {
    o->radius = Double(e, "radius", 0, true);
    o->height = Double(e, "height", 0, true);
    if (o->radius <= 0 || o->height <= 0) Error(e, "radius and height must be > 0");
  }
  o->movable = Bool(e, "movable", false);
  if (!Has(e, "movable")) Error(e, "missing required attribute 'movable'");
  if (o->movable) {
    o->mass = Double(e, "mass", 0, true);
    if (o->mass <= 0) Error(e, "mass must be > 0 for a movable object");
  }
  CheckChildren(e, {"body", "leds"}, "expected body, leds");
  if (const XMLElement* body = e->FirstChildElement("body"))
    LoadBody(body, &o->pose, &o->z);
  else if (needs_body)
    Error(e, "missing required <body position=\"x,y,z\" orientation=\"yaw,0,0\"/>");
  CheckFits(e, *o);
  if (const XMLElement* leds = e->FirstChildElement("leds")) {
    o->led_medium = Required(leds, "medium");
    for (auto* l = leds->FirstChildElement(); l; l = l->NextSiblingElement()) {
      if (std::string(l->Name()) != "led") {
        Error(l, "expected <led offset color/>");
        continue;
      }
      LedDef led;
      if (Has(l, "position") && !Has(l, "offset")) {
        // ARGoS 3 before offset/anchor: position is the offset from the body's origin.
        led.offset = Vector3(l, "position", Vec3::Zero(), true);
        if (!legacy_led_warned_)
          Warn(l,
               "legacy <led position=...>: read as offset from the body origin, anchor \"origin\" "
               "(current ARGoS: offset=\"x,y,z\" anchor=\"origin\")");
        legacy_led_warned_ = true;
      } else {
        led.offset = Vector3(l, "offset", Vec3::Zero(), true);
      }
      auto c = ParseColor(Str(l, "color", "black"));
      if (!c)
        Error(l, "bad colour '" + Str(l, "color") + "'");
      else
        led.color = *c;
      o->leds.push_back(led);
    }
  }
  return errors_->Size() == before;
}

bool Loader::LoadLight(const XMLElement* e, LightDef* l) {
  size_t before = errors_->Size();
  l->id = Required(e, "id");
  l->loc = Loc(e);
  l->position = Vector3(e, "position", Vec3::Zero(), true);
  Vector3(e, "orientation", Vec3::Zero());  // read (so not unknown), optional as in ARGoS's CPositionalEntity
  std::string c = Required(e, "color");
  auto col = ParseColor(c);
  if (!c.empty() && !col) Error(e, "bad colour '" + c + "'");
  if (col) l->color = *col;
  l->intensity = Double(e, "intensity", 1.0, true);
  l->medium = Required(e, "medium");
  return errors_->Size() == before;
}

void Loader::LoadFloor(const XMLElement* e) {
  FloorDef& f = model_->floor;
  f.loc = Loc(e);
  std::string source = Required(e, "source");
  if (source == "image") {
    f.source = FloorSource::Image;
    std::string path = Required(e, "path");
    if (path.empty()) return;
    f.path = ResolvePath(path);
    std::string err;
    if (!PathExists(f.path))
      Error(e, "floor image '" + path + "' not found");
    else if (!LoadPngBottomUp(f.path, model_->experiment.limits.floor_pixels, &f.width, &f.height, &f.pixels, &err))
      Error(e, "floor image '" + path + "': " + err);
  } else if (source == "loop_functions") {
    f.source = FloorSource::LoopFunctions;
    f.pixels_per_meter = Double(e, "pixels_per_meter", 100);
    if (f.pixels_per_meter <= 0 || f.pixels_per_meter > 1000) Error(e, "pixels_per_meter must be in (0, 1000]");
    // The raster is sampled from Lua pixel by pixel and held whole: a 10 km arena at 100
    // pixels/m would ask for 10^12 pixels (std::bad_alloc, found by fuzzing).
    const double w = model_->arena.size.x() * f.pixels_per_meter, h = model_->arena.size.y() * f.pixels_per_meter;
    if (!(w <= kMaxFloorSide && h <= kMaxFloorSide))
      Error(e, "the floor would be " + FormatDouble(std::floor(w)) + " x " + FormatDouble(std::floor(h)) +
                   " pixels (arena size x pixels_per_meter), more than " + std::to_string(kMaxFloorSide) +
                   " per side: lower pixels_per_meter");
  } else if (!source.empty()) {
    Error(e, "source must be image or loop_functions");
  }
}

void Loader::CheckArenaSize(const XMLElement* e) {
  const Vec3& size = model_->arena.size;
  const double limit = model_->experiment.limits.arena_size;
  if (size.x() <= 0 || size.y() <= 0)
    Error(e, "size must be > 0");
  else if (!(size.x() <= limit && size.y() <= limit))
    Error(e, "size " + FormatDouble(std::max(size.x(), size.y())) + " m is over the limit of " + FormatDouble(limit) +
                 " m per side (<system max_arena_size>)");
}

void Loader::LoadArena(const XMLElement* e) {
  model_->arena.size = Vector3(e, "size", Vec3(10, 10, 1), true);
  model_->arena.center = Vector3(e, "center", Vec3::Zero());
  CheckArenaSize(e);
  placed_.Cover(model_->arena.Min(), model_->arena.Max());
  if (Has(e, "positional_index")) Warn(e, "positional_index ignored (ARGoS ignores it too)");
  // Explicit entities in document order, then <distribute> blocks.
  for (auto* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    std::string name = c->Name();
    if (name == "foot-bot") {
      RobotDef r;
      if (LoadFootBot(c, &r)) {
        placed_.Add(FootprintOf(r));
        model_->robots.push_back(std::move(r));
      }
    } else if (name == "box" || name == "cylinder") {
      ObstacleDef o;
      if (LoadObstacle(c, &o)) {
        placed_.Add(FootprintOf(o));
        model_->obstacles.push_back(std::move(o));
      }
    } else if (name == "light") {
      LightDef l;
      if (LoadLight(c, &l)) model_->lights.push_back(std::move(l));
    } else if (name == "floor") {
      LoadFloor(c);
    } else if (name == "distribute") {
      // later
    } else {
      Error(c, "unsupported entity: essaim simulates foot-bot, box, cylinder, light, floor and distribute");
    }
    if (const char* id = Get(c, "id")) {
      if (name != "distribute" && !ids_.insert(id).second) Error(c, std::string("duplicate id '") + id + "'");
    }
  }
  RoomFor(e, 0, false);
  const auto placement_start = std::chrono::steady_clock::now();
  PlacedFootprints obstacles, robots_before;
  obstacles.Cover(model_->arena.Min(), model_->arena.Max());
  robots_before.Cover(model_->arena.Min(), model_->arena.Max());
  for (const ObstacleDef& o : model_->obstacles) obstacles.Add(FootprintOf(o));
  for (size_t i = 0; i < model_->robots.size(); ++i) {
    const RobotDef& r = model_->robots[i];
    std::string problem = OutsideArena(r);
    if (problem.empty()) problem = Overlap(r, obstacles, robots_before);
    robots_before.Add(FootprintOf(r));
    if (!problem.empty()) errors_->Add(r.loc.file, r.loc.line, r.loc.element, "foot-bot '" + r.id + "' " + problem);
  }
  for (auto* c = e->FirstChildElement("distribute"); c; c = c->NextSiblingElement("distribute")) LoadDistribute(c);
  model_->load_seconds.placement = SecondsSince(placement_start);
}

// A robot outside the arena breaks ARGoS's media grids: "" when `r` stands inside.
std::string Loader::OutsideArena(const RobotDef& r) const {
  Vec2 lo = model_->arena.Min(), hi = model_->arena.Max();
  if (r.pose.x >= lo.x() && r.pose.x <= hi.x() && r.pose.y >= lo.y() && r.pose.y <= hi.y()) return "";
  return "at (" + FormatDouble(r.pose.x) + ", " + FormatDouble(r.pose.y) + ") is outside the arena [" +
         FormatDouble(lo.x()) + ", " + FormatDouble(hi.x()) + "] x [" + FormatDouble(lo.y()) + ", " +
         FormatDouble(hi.y()) + "]";
}

// ARGoS refuses a robot that overlaps another entity. Checks `r` against every obstacle and
// the robots before it; "" when it stands free, else names the first obstacle, then the first
// robot, it overlaps. (Obstacles may overlap each other: walls share corners.)
std::string Loader::Overlap(const RobotDef& r, const PlacedFootprints& obstacles,
                            const PlacedFootprints& robots_before) const {
  const Footprint f = FootprintOf(r);
  const int k = obstacles.FirstOverlap(f);
  if (k >= 0) {
    const ObstacleDef& o = model_->obstacles[k];
    return std::string("overlaps ") + (o.kind == ShapeKind::Box ? "box" : "cylinder") + " '" + o.id + "' (line " +
           std::to_string(o.loc.line) + ")";
  }
  const int j = robots_before.FirstOverlap(f);
  if (j >= 0)
    return "overlaps foot-bot '" + model_->robots[j].id + "' (line " + std::to_string(model_->robots[j].loc.line) + ")";
  return "";
}

bool Loader::ParseGenerator(const XMLElement* e, Generator* g) {
  size_t before = errors_->Size();
  std::string method = Required(e, "method");
  using K = Generator::Kind;
  if (method == "uniform") {
    g->kind = K::Uniform;
    g->a = Vector3(e, "min", Vec3::Zero(), true);
    g->b = Vector3(e, "max", Vec3::Zero(), true);
    for (int i = 0; i < 3; ++i)
      if (g->a[i] > g->b[i]) Error(e, "min must be <= max component-wise");
  } else if (method == "gaussian") {
    g->kind = K::Gaussian;
    g->a = Vector3(e, "mean", Vec3::Zero(), true);
    g->b = Vector3(e, "std_dev", Vec3::Zero(), true);
  } else if (method == "constant") {
    g->kind = K::Constant;
    g->a = Vector3(e, "values", Vec3::Zero(), true);
  } else if (method == "grid") {
    g->kind = K::Grid;
    g->a = Vector3(e, "center", Vec3::Zero(), true);
    g->b = Vector3(e, "distances", Vec3::Zero(), true);
    auto layout = ParseVector(Str(e, "layout"), 3);
    if (!layout) {
      Error(e, "layout must be three integers nx,ny,nz");
    } else {
      for (int i = 0; i < 3; ++i) {
        // Range-checked before the int cast (layout="1e80,1,1" overflowed it: UBSan, fuzz_argos).
        const double v = (*layout)[i];
        g->layout[i] = v >= 1 && v <= 1e6 ? static_cast<int>(v) : 0;
        if (g->layout[i] <= 0) Error(e, "layout components must be > 0 (and at most 1000000)");
      }
    }
  } else if (!method.empty()) {
    Error(e, "method must be uniform, gaussian, constant or grid");
  }
  return errors_->Size() == before;
}

// Reads what a <distribute> block says, up to its prototype entity; false (errors reported)
// when nothing can be placed.
bool Loader::ReadDistribute(const XMLElement* e, DistributeBlock* b) {
  CheckChildren(e, {"position", "orientation", "entity"}, "expected position, orientation, entity");
  b->element = e;
  b->position = e->FirstChildElement("position");
  const XMLElement* orientation = e->FirstChildElement("orientation");
  const XMLElement* ent = b->entity = e->FirstChildElement("entity");
  if (!b->position || !orientation || !ent) {
    Error(e, "needs <position>, <orientation> and <entity> children");
    return false;
  }
  // Both generators are read, so both report their errors.
  bool ok = ParseGenerator(b->position, &b->position_gen) & ParseGenerator(orientation, &b->orientation_gen);
  b->quantity = Int(ent, "quantity", 0, true);
  b->max_trials = Int(ent, "max_trials", 0);
  b->base_num = Int(ent, "base_num", 0);
  if (b->max_trials < 0) Error(ent, "max_trials must be >= 0");
  b->proto = ent->FirstChildElement();
  if (!b->proto) {
    Error(ent, "needs one entity element (e.g. <foot-bot>)");
    return false;
  }
  b->kind = b->proto->Name();
  if (b->kind != "foot-bot" && b->kind != "box" && b->kind != "cylinder" && b->kind != "light") {
    Error(b->proto, "cannot distribute this entity: foot-bot, box, cylinder or light");
    return false;
  }
  if (b->quantity < 0)
    Error(ent, "quantity must be >= 0");
  else if (!RoomFor(ent, b->quantity, b->kind == "foot-bot"))
    return false;
  if (!ok) return false;
  b->base_id = Str(b->proto, "id");
  if (b->base_id.empty()) Error(b->proto, "missing required attribute 'id' (the base of the generated ids)");
  return !b->base_id.empty();
}

// The prototype is read once (also when quantity is 0, so its attributes are checked); each
// entity is a copy with its own id and pose. A distributed box or cylinder gets its <body>
// from the generators.
bool Loader::ReadPrototype(DistributeBlock* b) {
  if (b->kind == "foot-bot") return LoadFootBot(b->proto, &b->robot);
  if (b->kind == "light") return LoadLight(b->proto, &b->light);
  return LoadObstacle(b->proto, &b->obstacle, false);
}

Loader::Placement Loader::PlaceFootBot(const DistributeBlock& b, const std::string& id, const Vec3& p,
                                       const Pose2& pose) {
  RobotDef r = b.robot;
  r.id = id;
  r.pose = pose;
  r.z = p.z();
  std::string outside = OutsideArena(r);
  if (!outside.empty()) {  // a generator that reaches out of the arena: no retry helps
    Error(b.proto, "generated foot-bot '" + id + "' " + outside);
    return Placement::Failed;
  }
  Footprint f = FootprintOf(r);
  if (Collides(f)) return Placement::Overlaps;
  placed_.Add(f);
  model_->robots.push_back(std::move(r));
  return Placement::Placed;
}

Loader::Placement Loader::PlaceObstacle(const DistributeBlock& b, const std::string& id, const Vec3& p,
                                        const Pose2& pose) {
  ObstacleDef ob = b.obstacle;
  ob.id = id;
  ob.pose = pose;
  ob.z = p.z();
  std::string problem = ObstacleProblem(ob, model_->experiment.limits);
  if (!problem.empty()) {
    Error(b.position, "'" + id + "': " + problem);
    return Placement::Failed;
  }
  Footprint f = FootprintOf(ob);
  if (Collides(f)) return Placement::Overlaps;
  placed_.Add(f);
  model_->obstacles.push_back(std::move(ob));
  return Placement::Placed;
}

// One attempt: the next draw of both generators, rounded as ARGoS writes them.
Loader::Placement Loader::TryPlace(DistributeBlock* b, const std::string& id) {
  Vec3 p, o;
  if (!b->position_gen.Next(sim_rng_, b->draw, &p) || !b->orientation_gen.Next(sim_rng_, b->draw, &o)) {
    Error(b->element, "grid exhausted: layout has fewer cells than quantity (or a placement failed)");
    return Placement::Failed;
  }
  ++b->draw;
  for (int k = 0; k < 3; ++k) p[k] = RoundSignificant6(p[k]), o[k] = RoundSignificant6(o[k]);
  if (!Placeable(b->position, p)) return Placement::Failed;
  Pose2 pose{p.x(), p.y(), YawFromDegrees(o.x())};
  if (b->kind == "foot-bot") return PlaceFootBot(*b, id, p, pose);
  if (b->kind != "light") return PlaceObstacle(*b, id, p, pose);
  LightDef l = b->light;
  l.id = id;
  l.position = p;
  model_->lights.push_back(l);
  return Placement::Placed;
}

// Up to max_trials + 1 attempts for one entity (one on a grid, as ARGoS); false (an error
// reported) when it could not be placed.
bool Loader::PlaceDistributed(DistributeBlock* b, const std::string& id) {
  const bool grid = b->position_gen.kind == Generator::Kind::Grid;
  for (long long trial = 0; trial <= b->max_trials; ++trial) {
    Placement placement = TryPlace(b, id);
    if (placement == Placement::Placed) return true;
    if (placement == Placement::Failed) return false;
    if (grid) break;  // ARGoS: a grid allows no retry
  }
  if (grid)
    Error(b->entity, "could not place '" + id + "': its grid cell overlaps another entity (a grid allows no retry)");
  else
    Error(b->entity, "could not place '" + id + "' without overlap after " + std::to_string(b->max_trials + 1) +
                         " attempts (raise max_trials or give more room)");
  return false;
}

namespace {
/// Room for `more` elements, at least doubling: one move of what is there per block, and no
/// quadratic cost over many small blocks.
template <class Container>
void ReserveMore(Container* c, size_t more) {
  const size_t need = c->size() + more;
  if (need > c->capacity()) c->reserve(std::max(need, 2 * c->capacity()));
}
}  // namespace

void Loader::LoadDistribute(const XMLElement* e) {
  DistributeBlock b;
  if (!ReadDistribute(e, &b) || !ReadPrototype(&b)) return;
  // The block's quantity passed RoomFor: bounded by <system max_entities>.
  const size_t more = static_cast<size_t>(b.quantity);
  if (b.kind == "foot-bot")
    ReserveMore(&model_->robots, more);
  else if (b.kind == "light")
    ReserveMore(&model_->lights, more);
  else
    ReserveMore(&model_->obstacles, more);
  for (long long i = 0; i < b.quantity; ++i) {
    std::string id = b.base_id + std::to_string(i + b.base_num);
    if (!ids_.insert(id).second) {
      Error(b.proto, "generated id '" + id + "' is already used");
      return;
    }
    if (!PlaceDistributed(&b, id)) return;
  }
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
