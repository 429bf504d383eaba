// <distribute> blocks in the arena: the generators and the prototype read, then each copy
// placed with its own id, retried on overlap (the generators themselves: distribute.cpp).
#include <algorithm>
#include <string>

#include "core/strings.h"
#include "model/xml_loader_impl.h"

namespace essaim::xml_loader {

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

}  // namespace essaim::xml_loader
