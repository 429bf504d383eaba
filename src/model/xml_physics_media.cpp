// <physics_engines> (each <dynamics2d>, its <boundaries>, regions="K" strips, every entity in
// some region) and <media> (range_and_bearing, led).
#include <algorithm>
#include <set>
#include <string>

#include "core/strings.h"
#include "model/xml_loader_impl.h"

namespace essaim::xml_loader {

// Upper bounds on .argos numbers that size loops (docs/compatibility.md).
constexpr long long kMaxIterations = 100000;
// Regions of one engine split by regions="K": each is a Box2D world of its own.
constexpr long long kMaxPhysicsRegions = 256;

void Loader::LoadPhysics(const XMLElement* e) {
  ledger_.Visit(e);
  int engines = 0;
  for (auto* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    std::string name = c->Name();
    if (name != "dynamics2d") {
      Error(c, "unsupported physics engine: essaim simulates <dynamics2d> only");
      continue;
    }
    LoadEngine(c, engines++ == 0);
  }
  if (engines == 0) Error(e, "no physics engine: add <dynamics2d id=\"dyn2d\"/>");
  PhysicsDef& p = model_->physics;
  if (engines > 1) {
    std::set<std::string> ids;
    for (size_t r = 0; r < p.regions.size(); ++r)
      if (!ids.insert(p.regions[r].id).second)
        Error(engine_elements_[r], "duplicate engine id '" + p.regions[r].id + "'");
    for (size_t r = 0; r + 1 < p.regions.size(); ++r)
      if (!p.regions[r].Bounded())
        Warn(engine_elements_[r + 1],
             "never used: engine '" + p.regions[r].id + "' has no <boundaries> and takes every entity before it");
  }
}

// One <dynamics2d>: the first sets the parameters every region shares (sub-steps must match
// for the regions to step in lock step); the others only add their region.
void Loader::LoadEngine(const XMLElement* c, bool first) {
  PhysicsDef& p = model_->physics;
  PhysicsDef own;
  own.id = Str(c, "id", "dyn2d");
  long long iterations = Int(c, "iterations", 10);
  if (iterations < 1 || iterations > kMaxIterations)
    Error(c, "iterations must be between 1 and " + std::to_string(kMaxIterations));
  else
    own.iterations = static_cast<int>(iterations);
  own.gripping_rigidity = Double(c, "gripping_rigidity", own.gripping_rigidity);
  if (own.gripping_rigidity <= 0) Error(c, "gripping_rigidity must be > 0");
  CheckChildren(c, {"friction", "spatial_hash", "boundaries"}, "expected friction, spatial_hash, boundaries");
  if (const XMLElement* f = c->FirstChildElement("friction")) {
    own.box_linear_friction = Double(f, "box_linear_friction", own.box_linear_friction);
    own.box_angular_friction = Double(f, "box_angular_friction", own.box_angular_friction);
    own.cylinder_linear_friction = Double(f, "cylinder_linear_friction", own.cylinder_linear_friction);
    own.cylinder_angular_friction = Double(f, "cylinder_angular_friction", own.cylinder_angular_friction);
  }
  if (Has(c, "elevation") && Double(c, "elevation", 0) != 0) Warn(c, "elevation ignored");
  long long strips = Int(c, "regions", 1);
  if (strips < 1 || strips > kMaxPhysicsRegions)
    Error(c, "regions must be between 1 and " + std::to_string(kMaxPhysicsRegions));
  PhysicsRegionDef region;
  region.id = own.id;
  if (const XMLElement* b = c->FirstChildElement("boundaries")) LoadBoundaries(b, &region);
  if (first) {
    own.regions = {region};
    p = own;
    strips_ = static_cast<int>(std::clamp(strips, 1LL, static_cast<long long>(kMaxPhysicsRegions)));
  } else {
    if (own.iterations != p.iterations || own.gripping_rigidity != p.gripping_rigidity)
      Warn(c, "iterations and gripping_rigidity of the first engine apply to every engine");
    if (strips != 1) Error(c, "regions=\"K\" splits a single engine: not with several engines");
    p.regions.push_back(region);
  }
  engine_elements_.push_back(c);
}

// <boundaries><top height/><bottom height/><sides><vertex point="x,y"/>...</sides>.
void Loader::LoadBoundaries(const XMLElement* b, PhysicsRegionDef* region) {
  CheckChildren(b, {"top", "bottom", "sides"}, "expected top, bottom, sides");
  const XMLElement* top = b->FirstChildElement("top");
  const XMLElement* bottom = b->FirstChildElement("bottom");
  const XMLElement* sides = b->FirstChildElement("sides");
  if (!top || !bottom || !sides) {
    Error(b, "<boundaries> needs <top height>, <bottom height> and <sides>");
    return;
  }
  region->top = Double(top, "height", 0, true);
  region->bottom = Double(bottom, "height", 0, true);
  CheckChildren(sides, {"vertex"}, "expected vertex");
  for (const XMLElement* v = sides->FirstChildElement("vertex"); v; v = v->NextSiblingElement("vertex")) {
    const std::string text = Required(v, "point");
    auto d = ParseVector(text, 2);
    if (!d) {
      if (!text.empty()) Error(v, "attribute 'point': '" + text + "' must be two comma-separated numbers");
      return;
    }
    region->sides.emplace_back((*d)[0], (*d)[1]);
  }
  std::string problem = RegionProblem(*region);
  if (!problem.empty()) Error(sides, problem);
  if (!problem.empty()) region->sides.clear();
}

// After the arena: regions="K" becomes strips of it, and every entity must lie in some
// engine's region (ARGoS refuses an entity no engine takes).
void Loader::FinishPhysicsRegions() {
  PhysicsDef& p = model_->physics;
  if (strips_ > 1) p.regions = ArenaStrips(model_->arena, p.id, strips_);
  if (p.regions.size() < 2 && !(p.regions.size() == 1 && p.regions[0].Bounded())) {
    p.regions.clear();
    return;
  }
  auto check = [&](const std::string& kind, const std::string& id, const Pose2& pose) {
    if (RegionOf(p.regions, {pose.x, pose.y}, -1) >= 0) return;
    Error(engine_elements_.empty() ? nullptr : engine_elements_.back(),
          kind + " '" + id + "' at (" + FormatDouble(pose.x) + ", " + FormatDouble(pose.y) +
              ") lies in no physics engine's <boundaries>");
  };
  for (const RobotDef& r : model_->robots) check("foot-bot", r.id, r.pose);
  for (const ObstacleDef& o : model_->obstacles) check(o.kind == ShapeKind::Box ? "box" : "cylinder", o.id, o.pose);
}

void Loader::LoadMedia(const XMLElement* e) {
  ledger_.Visit(e);
  for (auto* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    std::string name = c->Name();
    if (name == "range_and_bearing") {
      RabMediumDef m;
      m.id = Required(c, "id");
      m.check_occlusions = Bool(c, "check_occlusions", true);
      std::string index = Str(c, "index", "grid");
      if (index != "grid" && index != "dummy") Error(c, "index must be grid or dummy");
      model_->rab_media.push_back(m);
    } else if (name == "led") {
      LedMediumDef m;
      m.id = Required(c, "id");
      model_->led_media.push_back(m);
    } else {
      Error(c, "unknown medium: expected <range_and_bearing> or <led>");
    }
  }
}

}  // namespace essaim::xml_loader
