// The Model: everything fixed once an experiment is loaded (MuJoCo's mjModel). Plain defs
// with defaults and units; built by the loader, then const and shared by every thread.
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/math.h"
#include "model/device_params.h"
#include "model/device_table.h"

namespace essaim {

/// Foot-bot constants, as ARGoS's foot-bot entity and its dynamics2d model define them.
namespace footbot {
constexpr double kRadius = 0.085036758;             // m
constexpr double kHeight = 0.146899733;             // m
constexpr double kBaseMass = 1.6;                   // kg
constexpr double kGripperMass = kBaseMass / 20;     // kg, a second body pinned to the base's centre
constexpr double kMass = kBaseMass + kGripperMass;  // kg, what the wheels' force moves
constexpr double kAxisLength = 0.14;                // m between the wheels
constexpr double kMaxForce = 15.0;                  // N
constexpr double kMaxTorque = 150.0;                // N·m
constexpr double kRabElevation = 0.1;               // m
constexpr double kProximityElevation = 0.06;        // m
constexpr double kScannerElevation = 0.123199866;   // m
constexpr double kCameraElevation = 0.288699733;    // m
constexpr int kLedCount = 13;
}  // namespace footbot

/// Where something came from in the XML, for error messages.
struct SourceLoc {
  std::string file;
  int line = 0;
  std::string element;
};

using AttrMap = std::map<std::string, std::string>;

struct DeviceConfig {
  DeviceType type = DeviceType::Count;
  std::string implementation;
  AttrMap attrs;        // every attribute as written
  DeviceParams params;  // parsed once at load
  SourceLoc loc;
  /// Attribute text, or the device table's default.
  std::string Attr(const std::string& name) const;
};

struct XmlNode {
  std::string name;
  int line = 0;                                                 // in the model's file
  std::vector<std::pair<std::string, std::string>> attributes;  // in the file's order
  std::string text;
  std::vector<XmlNode> children;
};

/// A <lua_controller>, or a C++ controller: an element whose tag is a REGISTER_CONTROLLER
/// label, with an optional library="..." (docs/cpp-controllers.md).
struct ControllerDef {
  std::string id;
  std::string script;   // path as resolved (empty: no script)
  std::string label;    // C++: the element's tag
  std::string library;  // C++: the library's resolved path ("": none named)
  XmlNode xml;          // C++: the element as written (Init gets its <params>)
  bool Cpp() const { return !label.empty(); }
  AttrMap params;                       // all <params> attributes, as strings (ARGoS)
  std::vector<DeviceConfig> actuators;  // sorted by XML tag (ARGoS applies them so)
  std::vector<DeviceConfig> sensors;    // sorted by XML tag
  SourceLoc loc;
  const DeviceConfig* Find(DeviceType type) const;
  bool Has(DeviceType type) const { return Find(type) != nullptr; }
};

enum class DischargeModel { None, Time, Motion, TimeMotion };

struct BatteryDef {
  DischargeModel model = DischargeModel::None;  // no <battery>: never depletes
  double start_charge = 1.0;
  double full_charge = 1.0;
  double delta = 1e-5;                                                 // time: per tick
  double pos_delta = 1e-3;                                             // motion: per m
  double orient_delta = 1e-3;                                          // motion: per rad
  double time_factor = 1e-5, pos_factor = 1e-3, orient_factor = 1e-3;  // time_motion
};

struct RobotDef {
  std::string id;
  Pose2 pose;
  double z = 0;
  int controller = -1;        // index into Model::controllers
  std::string controller_id;  // <controller config="...">
  int controller_line = 0;
  AttrMap params;          // the controller's, or the robot's own <params> (replaces)
  double rab_range = 3.0;  // m
  int rab_data_size = 10;  // bytes
  double camera_aperture = DegToRad(70);
  double max_force = footbot::kMaxForce;
  double max_torque = footbot::kMaxTorque;
  BatteryDef battery;
  SourceLoc loc;
};

struct LedDef {
  Vec3 offset = Vec3::Zero();
  Color color;
};

enum class ShapeKind { Box, Cylinder };

/// A box or a cylinder, static or movable.
struct ObstacleDef {
  std::string id;
  ShapeKind kind = ShapeKind::Box;
  Pose2 pose;  // centre of the base; yaw
  double z = 0;
  double size_x = 0, size_y = 0;  // box
  double radius = 0;              // cylinder
  double height = 0;
  bool movable = false;
  double mass = 0;  // kg, movable only
  std::vector<LedDef> leds;
  std::string led_medium;
  SourceLoc loc;
};

struct LightDef {
  std::string id;
  Vec3 position = Vec3::Zero();
  Color color;
  double intensity = 1.0;
  std::string medium;
  SourceLoc loc;
};

enum class FloorSource { None, Image, LoopFunctions };

struct FloorDef {
  FloorSource source = FloorSource::None;
  std::string path;               // image, resolved
  double pixels_per_meter = 100;  // loop-function floors are rasterised at this density
  /// Image pixels, bottom row first (row 0 = arena min y), RGB. Filled by the loader for
  /// images only; a loop-function floor is sampled into the World's FloorRaster (sim/world.cpp).
  int width = 0, height = 0;
  std::vector<Color> pixels;
  SourceLoc loc;
};

struct RabMediumDef {
  std::string id;
  bool check_occlusions = true;
};

struct LedMediumDef {
  std::string id;
};

/// An XML element as written: C++ loop functions get theirs whole in Init(TConfigurationNode&).
struct LoopFunctionsDef {
  std::string script;  // resolved path; empty = none
  /// C++ loop functions (library and/or label, no script): the library's resolved path
  /// ("": found by label in ARGOS_PLUGIN_PATH), the label, the whole element.
  std::string library;
  std::string label;
  XmlNode xml;
  bool Cpp() const { return !label.empty(); }
  AttrMap params;  // attributes of <loop_functions>
  /// Its child elements (<params reset_all="true"/>...): name → attributes, first of a name.
  std::map<std::string, AttrMap> children;
  SourceLoc loc;
};

/// Sizes and counts essaim accepts, checked before anything is allocated (from the file and
/// from add_entity); each can be raised with <system max_...> (docs/safety.md). The defaults
/// keep a run well inside a few GiB.
struct LimitsDef {
  double arena_size = 10000;         // m, per side: <system max_arena_size>
  double entity_size = 1000;         // m, a box's side or height, a cylinder's diameter or height
  long long floor_pixels = 1 << 26;  // pixels of an image floor, read from the PNG header
  long long entities = 0;            // foot-bots, boxes, cylinders and lights, added ones included; 0: as memory allows
};

struct ExperimentDef {
  LimitsDef limits;
  int threads = 0;                 // 0 = main thread only
  long long lua_budget = -1;       // <system lua_budget>: instructions per step() call; -1 = default
  long long lua_init_budget = -1;  // <system lua_init_budget>: per init()/reset()/top level; -1 = default
  long long lua_memory_mib = -1;   // <system lua_memory>: MiB per Lua state; -1 = default
  int ticks_per_second = 10;
  uint64_t length_ticks = 0;  // 0 = unlimited
  uint64_t seed = 0;
  double TickLength() const { return 1.0 / ticks_per_second; }
};

/// The part of the arena one physics engine owns (ARGoS's <boundaries>): a polygon in the
/// floor plane, counter-clockwise, between two heights. No vertices: the whole arena.
struct PhysicsRegionDef {
  std::string id;
  std::vector<Vec2> sides;     // m, counter-clockwise; empty: unbounded
  double bottom = 0, top = 0;  // m; only read when `sides` is not empty
  bool Bounded() const { return !sides.empty(); }
};

struct PhysicsDef {
  std::string id = "dyn2d";
  /// One per engine when several are declared, or the strips of `regions="K"`; empty or
  /// one: a single Box2D world for the whole arena.
  std::vector<PhysicsRegionDef> regions;
  int iterations = 10;  // sub-steps per tick
  double box_linear_friction = 1.49, box_angular_friction = 1.49;
  double cylinder_linear_friction = 1.49, cylinder_angular_friction = 1.49;
  double gripping_rigidity = 10000;  // N: force cap of a gripper's hold (N·m for its torque)
};

struct ArenaDef {
  Vec3 size = Vec3(10, 10, 1);
  Vec3 center = Vec3::Zero();
  Vec2 Min() const { return {center.x() - size.x() / 2, center.y() - size.y() / 2}; }
  Vec2 Max() const { return {center.x() + size.x() / 2, center.y() + size.y() / 2}; }
};

/// Seconds the loader spent (summary.json's setup_seconds): the whole load, the file read
/// included, and of it the placing of entities (overlap checks, <distribute>).
struct LoadSeconds {
  double total = 0, placement = 0;
};

struct Model {
  std::string file;                    // the .argos path as given
  std::string dir;                     // its folder
  std::string file_hash;               // fnv1a64 of the file content
  std::vector<std::string> overrides;  // --set lines applied
  ExperimentDef experiment;
  ArenaDef arena;
  PhysicsDef physics;
  std::vector<ControllerDef> controllers;
  std::vector<RobotDef> robots;  // explicit ones, then <distribute> blocks
  std::vector<ObstacleDef> obstacles;
  std::vector<LightDef> lights;
  FloorDef floor;
  std::vector<RabMediumDef> rab_media;
  std::vector<LedMediumDef> led_media;
  LoopFunctionsDef loop_functions;
  LoadSeconds load_seconds;  // how long this load took, not part of the experiment
};

}  // namespace essaim
