// What the ARGoS API library (libessaim_argos_api, api/) asks of the running
// experiment: an interface of plain types, implemented over the EntityStore by StoreWorld
// (store_world.h). The library keeps no essaim type of its own, so one copy of it serves
// the essaim binary, the Python module and the tests alike.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

struct lua_State;

namespace essaim {

/// An entity of the world: kind as EntityKind (foot-bot 0, box 1, cylinder 2, light 3), and
/// its serial in the EntityStore (a robot's index for foot-bots).
struct ArgosRef {
  int kind = 0;
  uint32_t serial = 0;
};
constexpr int kArgosFootBot = 0, kArgosBox = 1, kArgosCylinder = 2, kArgosLight = 3;

struct ArgosPose {
  double x = 0, y = 0, z = 0, yaw = 0;  // m, rad
};

struct ArgosRgb {
  uint8_t r = 0, g = 0, b = 0;
};

/// A box or cylinder to add, or what one is.
struct ArgosBody {
  std::string id;
  int kind = kArgosBox;
  ArgosPose pose;
  double size[3] = {0, 0, 0};  // box
  double radius = 0, height = 0;
  double mass = 1;
  bool movable = false;
  std::vector<std::vector<double>> led_offsets;  // {x, y, z} from the base centre
  std::vector<ArgosRgb> led_colors;
  std::string medium;  // <led> medium of the LEDs
};

struct ArgosLight {
  std::string id;
  double position[3] = {0, 0, 0};
  ArgosRgb color;
  double intensity = 1;
  std::string medium;
};

/// A foot-bot to add: CFootBotEntity's constructor arguments.
struct ArgosRobot {
  std::string id;
  std::string controller_id;  // a <lua_controller id> of the .argos file
  ArgosPose pose;
  double rab_range = 3;  // m
  uint64_t rab_data_size = 10;
  double camera_aperture = 1.2740903539558606;  // rad
};

class ArgosWorld {
 public:
  virtual ~ArgosWorld() = default;
  virtual uint64_t Tick() const = 0;
  virtual uint64_t Seed() const = 0;
  virtual uint64_t LengthTicks() const = 0;
  virtual double TickLength() const = 0;  // s
  virtual void Arena(double size[3], double center[3]) const = 0;
  virtual std::vector<std::string> LedMedia() const = 0;
  /// Live entities of `kind` (all when -1), in creation order.
  virtual std::vector<ArgosRef> Entities(int kind) const = 0;
  /// Changes whenever an entity is added or removed (not when one moves).
  virtual uint64_t LayoutVersion() const = 0;
  virtual bool Live(const ArgosRef& e) const = 0;
  virtual std::string Id(const ArgosRef& e) const = 0;
  /// The entity's pose; false when it is no longer live.
  virtual bool Pose(const ArgosRef& e, ArgosPose* pose) const = 0;
  virtual bool Movable(const ArgosRef& e) const = 0;
  /// Moves a body there when it overlaps no other (or `check_only`: says whether it would).
  virtual bool Move(const ArgosRef& e, const ArgosPose& pose, bool check_only, bool ignore_collisions) = 0;
  /// A box's or cylinder's shape (pose as made).
  virtual ArgosBody Body(const ArgosRef& e) const = 0;
  virtual int LedCount(const ArgosRef& e) const = 0;
  virtual ArgosRgb Led(const ArgosRef& e, int k) const = 0;
  virtual void SetLed(const ArgosRef& e, int k, const ArgosRgb& color) = 0;
  virtual void SetMedium(const ArgosRef& e, const std::string& medium) = 0;
  virtual ArgosLight Light(const ArgosRef& e) const = 0;
  virtual void SetLight(const ArgosRef& e, const ArgosLight& light) = 0;
  /// Adds a box, cylinder or light; false with `error` (duplicate id, overlap, limits).
  virtual bool Add(const ArgosBody& body, ArgosRef* added, std::string* error) = 0;
  virtual bool Add(const ArgosLight& light, ArgosRef* added, std::string* error) = 0;
  /// Adds a foot-bot and makes its controller (script and init() run); false with `error`
  /// (duplicate id, unknown controller, outside the arena, limits, the script failing).
  virtual bool Add(const ArgosRobot& robot, ArgosRef* added, std::string* error) = 0;
  virtual bool Remove(const ArgosRef& e) = 0;
  virtual std::string ControllerId(uint32_t robot) const = 0;
  /// The robot's Lua state (kept after its controller failed), null when it has none.
  virtual lua_State* LuaState(uint32_t robot) = 0;
  virtual bool ControllerOk(uint32_t robot) const = 0;
  virtual void Log(bool error, const std::string& line) = 0;
  virtual void FloorChanged() = 0;
};

}  // namespace essaim
