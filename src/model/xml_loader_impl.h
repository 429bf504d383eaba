// The .argos loader's one class, private to src/model: its member functions live in the
// xml_*.cpp files beside it, one section of the document each (see xml_loader.cpp's Load).
// Nothing outside src/model includes this header (tools/check_layers.py).
#pragma once
#include <tinyxml2.h>

#include <cmath>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/error_list.h"
#include "core/math.h"
#include "core/rng.h"
#include "model/attribute_ledger.h"
#include "model/distribute.h"
#include "model/limits.h"
#include "model/model.h"
#include "model/physics_regions.h"
#include "model/placement.h"
#include "model/xml_loader.h"
#include "model/xml_overrides.h"

namespace essaim::xml_loader {

using tinyxml2::XMLElement;

/// The element as written, children and text included (C++ loop functions and controllers
/// get it whole; xml_attributes.cpp).
XmlNode ToXmlNode(const XMLElement* e);

// Reads one document into a Model, collecting every error on the way.
class Loader {
 public:
  Loader(const std::string& path, const LoadOptions& options, ErrorList* errors, ErrorList* warnings)
      : path_(path), options_(options), errors_(errors), warnings_(warnings) {}

  std::unique_ptr<Model> Load(const std::string& text);

 private:
  // ---- error helpers
  void Error(const XMLElement* e, const std::string& msg) {
    errors_->Add(path_, e ? e->GetLineNum() : 0, e ? e->Name() : "", msg);
  }
  void Warn(const XMLElement* e, const std::string& msg) {
    if (warnings_) warnings_->Add(path_, e ? e->GetLineNum() : 0, e ? e->Name() : "", msg);
  }
  SourceLoc Loc(const XMLElement* e) const { return {path_, e->GetLineNum(), e->Name()}; }
  // Box2D holds positions and angles as floats and asserts they are finite: a coordinate
  // of 1e39 m, or a yaw of 1e300 degrees, used to abort the process (found by fuzz_argos).
  bool Placeable(const XMLElement* e, const Vec3& position) {
    if (position.cwiseAbs().maxCoeff() <= kMaxCoordinate) return true;
    Error(e, "position beyond 1e6 m from the origin on an axis: Box2D cannot hold it");
    return false;
  }
  /// Any finite angle is an angle: beyond a turn it is reduced (exactly, by fmod), so that
  /// its radians stay a float; angles within ±360 degrees are used as written.
  static double YawFromDegrees(double degrees) {
    return DegToRad(std::abs(degrees) > 360 ? std::fmod(degrees, 360.0) : degrees);
  }
  static constexpr int kMaxFloorSide = 8192;  // pixels of a loop-function floor

  // ---- attributes (xml_attributes.cpp): typed access, reporting and returning a default on
  // bad text. Every read goes through Get, which records it: what nobody read is reported
  // (ReportUnknownAttributes).
  const char* Get(const XMLElement* e, const char* name) {
    ledger_.Read(e, name);
    return e->Attribute(name);
  }
  bool Has(const XMLElement* e, const char* name) { return Get(e, name) != nullptr; }
  std::string Str(const XMLElement* e, const char* name, const std::string& def = "") {
    const char* v = Get(e, name);
    return v ? v : def;
  }
  std::string Required(const XMLElement* e, const char* name) {
    const char* v = Get(e, name);
    if (!v) Error(e, std::string("missing required attribute '") + name + "'");
    return v ? v : "";
  }
  double Double(const XMLElement* e, const char* name, double def, bool required = false);
  long long Int(const XMLElement* e, const char* name, long long def, bool required = false);
  bool Bool(const XMLElement* e, const char* name, bool def);
  Vec3 Vector3(const XMLElement* e, const char* name, const Vec3& def, bool required = false);
  void CheckChildren(const XMLElement* e, const std::set<std::string>& allowed, const char* what);
  std::string ResolvePath(const std::string& rel) const;
  void ReportUnknownAttributes(const XMLElement* root);
  std::string NoEndHint() const;

  // ---- <framework> (xml_framework.cpp)
  void LoadFramework(const XMLElement* e);
  void LoadWatchdog(const XMLElement* sys, ExperimentDef* x);
  void LoadLimits(const XMLElement* sys, LimitsDef* limits);

  // ---- <controllers> (xml_controllers.cpp)
  void LoadControllers(const XMLElement* e);
  /// One kind of controller (a file each): <lua_controller> in xml_lua_controller.cpp.
  void LoadLuaController(const XMLElement* c);
  /// A C++ controller: the tag a REGISTER_CONTROLLER label (xml_cpp_controller.cpp).
  void LoadCppController(const XMLElement* c);
  /// What every kind holds after its id (xml_controllers.cpp); returns <params>, or null.
  const XMLElement* LoadControllerBody(const XMLElement* c, ControllerDef* def);
  void LoadDevices(const XMLElement* list, bool sensors, ControllerDef* c);

  // ---- <physics_engines> and <media> (xml_physics_media.cpp)
  void LoadPhysics(const XMLElement* e);
  void LoadEngine(const XMLElement* c, bool first);
  void LoadBoundaries(const XMLElement* b, PhysicsRegionDef* region);
  void FinishPhysicsRegions();
  void LoadMedia(const XMLElement* e);

  // ---- <loop_functions> (xml_loop_functions.cpp)
  void LoadLoopFunctions(const XMLElement* e);
  void LoadCppLoopFunctions(const XMLElement* e, LoopFunctionsDef* lf);
  void ReadAllBelow(const XMLElement* e);
  /// A library="..." as ARGoS finds it (xml_library.cpp): resolved path, or "" after an error at `e`.
  std::string ResolveLibrary(const XMLElement* e, const std::string& library);

  // ---- <arena> and its entities (xml_arena.cpp)
  void LoadArena(const XMLElement* e);
  void CheckArenaSize(const XMLElement* e);
  /// False (an error at `e`) when `more` entities would take the experiment over its limit.
  bool RoomFor(const XMLElement* e, long long more, bool robots);
  /// An error at `e` when the obstacle is over the size limit or out of range.
  void CheckFits(const XMLElement* e, const ObstacleDef& o) {
    std::string problem = ObstacleProblem(o, model_->experiment.limits);
    if (!problem.empty()) Error(e, problem);
  }
  bool LoadFootBot(const XMLElement* e, RobotDef* r);
  bool LoadObstacle(const XMLElement* e, ObstacleDef* o, bool needs_body = true);
  bool LoadLight(const XMLElement* e, LightDef* l);
  void LoadFloor(const XMLElement* e);
  void LoadBody(const XMLElement* body, Pose2* pose, double* z);
  Footprint FootprintOf(const RobotDef& r) const {
    Footprint f;
    f.center = {r.pose.x, r.pose.y};
    f.radius = footbot::kRadius;
    return f;
  }
  Footprint FootprintOf(const ObstacleDef& o) const { return ObstacleFootprint(o); }
  std::string OutsideArena(const RobotDef& r) const;
  std::string Overlap(const RobotDef& r, const PlacedFootprints& obstacles,
                      const PlacedFootprints& robots_before) const;
  bool Collides(const Footprint& f) const { return placed_.Collides(f); }

  // ---- <distribute> (xml_distribute.cpp): read the block, then place `quantity` copies of
  // its prototype
  struct DistributeBlock {
    const XMLElement* element = nullptr;   // <distribute>
    const XMLElement* position = nullptr;  // its <position>
    const XMLElement* entity = nullptr;    // its <entity>
    const XMLElement* proto = nullptr;     // the entity inside <entity>
    Generator position_gen, orientation_gen;
    long long quantity = 0, max_trials = 0, base_num = 0;
    std::string kind;  // foot-bot, box, cylinder or light
    std::string base_id;
    RobotDef robot;  // the prototype of its kind, read once
    ObstacleDef obstacle;
    LightDef light;
    int draw = 0;  // grid cell counter: every attempt consumes one (a retry is fatal on a grid)
  };
  enum class Placement { Placed, Overlaps, Failed };
  void LoadDistribute(const XMLElement* e);
  bool ReadDistribute(const XMLElement* e, DistributeBlock* b);
  bool ReadPrototype(DistributeBlock* b);
  bool PlaceDistributed(DistributeBlock* b, const std::string& id);
  Placement TryPlace(DistributeBlock* b, const std::string& id);
  Placement PlaceFootBot(const DistributeBlock& b, const std::string& id, const Vec3& p, const Pose2& pose);
  Placement PlaceObstacle(const DistributeBlock& b, const std::string& id, const Vec3& p, const Pose2& pose);
  bool ParseGenerator(const XMLElement* e, Generator* g);

  // ---- across sections (xml_loader.cpp): robots bound to controllers, media and floor checked
  void CheckReferences();

  std::string path_;
  std::string dir_;
  const LoadOptions& options_;
  ErrorList* errors_;
  ErrorList* warnings_;
  std::unique_ptr<Model> model_;
  std::set<std::string> ids_;
  PlacedFootprints placed_;
  Rng sim_rng_;
  AttributeLedger ledger_;
  std::vector<std::pair<OverrideTarget, std::string>> set_targets_;  // where each --set landed
  std::vector<const XMLElement*> engine_elements_;                   // each <dynamics2d>, for errors about its region
  int strips_ = 1;                                                   // the first engine's regions="K"
  bool legacy_led_warned_ = false;                                   // one warning per file for <led position=...>
};

}  // namespace essaim::xml_loader
