// <arena>: its size, the entities written out (foot-bots, boxes, cylinders, lights, the floor),
// the entity count limit, and where foot-bots stand: inside the arena, overlapping nothing.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "core/color.h"
#include "core/paths.h"
#include "core/stopwatch.h"
#include "core/strings.h"
#include "model/floor_image.h"
#include "model/xml_loader_impl.h"

namespace essaim::xml_loader {

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

}  // namespace essaim::xml_loader
