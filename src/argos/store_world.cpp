#include "argos/store_world.h"

#include <cmath>

#include "argos/argos_session.h"
#include "model/distribute.h"

namespace essaim {

namespace {
Color ToColor(const ArgosRgb& c) { return Color{c.r, c.g, c.b, 255}; }
ArgosRgb ToRgb(const Color& c) { return {c.r, c.g, c.b}; }
}  // namespace

void StoreWorld::Arena(double size[3], double center[3]) const {
  for (int k = 0; k < 3; ++k) size[k] = model_.arena.size[k], center[k] = model_.arena.center[k];
}

std::vector<std::string> StoreWorld::LedMedia() const {
  std::vector<std::string> ids;
  for (const LedMediumDef& m : model_.led_media) ids.push_back(m.id);
  return ids;
}

std::vector<ArgosRef> StoreWorld::Entities(int kind) const {
  std::vector<ArgosRef> out;
  for (const EntityRef& e : entities_.All())
    if (kind < 0 || static_cast<int>(e.kind) == kind) out.push_back({static_cast<int>(e.kind), e.serial});
  return out;
}

// Added() only grows and All() only shrinks when nothing is added: the pair changes on every
// addition or removal.
uint64_t StoreWorld::LayoutVersion() const { return entities_.LayoutVersion(); }

bool StoreWorld::Pose(const ArgosRef& e, ArgosPose* pose) const {
  const int index = entities_.IndexOf(Ref(e));
  if (index < 0) return false;
  const Vec3 p = entities_.Position(Ref(e), index);
  *pose = {p.x(), p.y(), p.z(), entities_.Yaw(Ref(e), index)};
  return true;
}

bool StoreWorld::Overlaps(const ArgosRef& e, const Pose2& pose) const {
  const EntityRef self = Ref(e);
  const int self_index = entities_.IndexOf(self);
  Footprint moved;
  if (self.kind == EntityKind::FootBot) {
    moved.center = {pose.x, pose.y}, moved.radius = footbot::kRadius;
  } else {
    ObstacleDef def = entities_.Obstacle(self_index);
    def.pose = pose;
    moved = ObstacleFootprint(def);
  }
  for (size_t i = 0; i < model_.robots.size(); ++i) {
    if (self.kind == EntityKind::FootBot && static_cast<int>(i) == self_index) continue;
    Footprint robot;
    const Pose2 at = entities_.RobotPose(static_cast<int>(i));
    robot.center = {at.x, at.y}, robot.radius = footbot::kRadius;
    if (FootprintsOverlap(moved, robot)) return true;
  }
  for (size_t i = 0; i < model_.obstacles.size(); ++i) {
    const EntityRef other = entities_.ObstacleRef(static_cast<int>(i));
    if (other.kind == self.kind && other.serial == self.serial) continue;
    ObstacleDef def = entities_.Obstacle(static_cast<int>(i));
    const Vec3 at = entities_.Position(other, static_cast<int>(i));
    def.pose = {at.x(), at.y(), entities_.Yaw(other, static_cast<int>(i))};
    if (FootprintsOverlap(moved, ObstacleFootprint(def))) return true;
  }
  return false;
}

bool StoreWorld::Move(const ArgosRef& e, const ArgosPose& pose, bool check_only, bool ignore_collisions) {
  const EntityRef ref = Ref(e);
  const int index = entities_.IndexOf(ref);
  const Pose2 target{pose.x, pose.y, pose.yaw};
  if (ref.kind != EntityKind::Light) {
    // Static bodies are built into the physics at the first step (as ARGoS's): only Init moves them.
    if (!entities_.Movable(ref, index) && tick_ > 0) return false;
    if (!ignore_collisions && Overlaps(e, target)) return false;
  }
  if (!check_only) entities_.SetPose(ref, index, target);
  return true;
}

ArgosBody StoreWorld::Body(const ArgosRef& e) const {
  const ObstacleDef& o = entities_.Obstacle(entities_.IndexOf(Ref(e)));
  ArgosBody b;
  b.id = o.id;
  b.kind = e.kind;
  b.pose = {o.pose.x, o.pose.y, o.z, o.pose.yaw};
  b.size[0] = o.size_x, b.size[1] = o.size_y, b.size[2] = o.height;
  b.radius = o.radius, b.height = o.height, b.mass = o.mass, b.movable = o.movable;
  for (const LedDef& led : o.leds) {
    b.led_offsets.push_back({led.offset.x(), led.offset.y(), led.offset.z()});
    b.led_colors.push_back(ToRgb(led.color));
  }
  b.medium = o.led_medium;
  return b;
}

ArgosRgb StoreWorld::Led(const ArgosRef& e, int k) const {
  return ToRgb(entities_.Led(Ref(e), entities_.IndexOf(Ref(e)), k));
}

void StoreWorld::SetLed(const ArgosRef& e, int k, const ArgosRgb& color) {
  entities_.SetLed(Ref(e), entities_.IndexOf(Ref(e)), k, ToColor(color));
}

std::string StoreWorld::MediumProblem(const std::string& medium) const {
  for (const LedMediumDef& m : model_.led_media)
    if (m.id == medium) return "";
  return "medium '" + medium + "' is not declared in <media> (<led id=\"" + medium + "\"/>)";
}

void StoreWorld::SetMedium(const ArgosRef& e, const std::string& medium) {
  entities_.SetMedium(Ref(e), entities_.IndexOf(Ref(e)), medium);
}

ArgosLight StoreWorld::Light(const ArgosRef& e) const {
  const LightDef& l = entities_.Light(entities_.IndexOf(Ref(e)));
  ArgosLight out;
  out.id = l.id;
  for (int k = 0; k < 3; ++k) out.position[k] = l.position[k];
  out.color = ToRgb(l.color), out.intensity = l.intensity, out.medium = l.medium;
  return out;
}

void StoreWorld::SetLight(const ArgosRef& e, const ArgosLight& light) {
  const EntityRef ref = Ref(e);
  const int index = entities_.IndexOf(ref);
  entities_.SetPose(ref, index, {light.position[0], light.position[1], 0});
  entities_.SetLightColor(index, ToColor(light.color));
  entities_.SetLightIntensity(index, light.intensity);
  if (light.medium != entities_.Light(index).medium) entities_.SetMedium(ref, index, light.medium);
}

namespace {
ObstacleDef ToObstacle(const ArgosBody& b) {
  ObstacleDef o;
  o.id = b.id;
  o.kind = b.kind == kArgosBox ? ShapeKind::Box : ShapeKind::Cylinder;
  o.pose = {b.pose.x, b.pose.y, b.pose.yaw};
  o.z = b.pose.z;
  o.size_x = b.size[0], o.size_y = b.size[1];
  o.radius = b.radius;
  o.height = b.kind == kArgosBox ? b.size[2] : b.height;
  o.movable = b.movable, o.mass = b.mass;
  for (size_t k = 0; k < b.led_offsets.size(); ++k)
    o.leds.push_back({Vec3(b.led_offsets[k][0], b.led_offsets[k][1], b.led_offsets[k][2]), ToColor(b.led_colors[k])});
  o.led_medium = b.medium;
  o.loc.element = "AddEntity";
  return o;
}
}  // namespace

bool StoreWorld::Add(const ArgosBody& body, ArgosRef* added, std::string* error) {
  const ObstacleDef def = ToObstacle(body);
  if (entities_.HasId(def.id)) *error = "id '" + def.id + "' is already used";
  if (error->empty() && def.movable && !(def.mass > 0)) *error = "mass must be > 0 for a movable object";
  if (error->empty() && !def.led_medium.empty()) *error = MediumProblem(def.led_medium);
  if (error->empty()) *error = entities_.ObstacleProblemNow(def);
  if (error->empty()) *error = entities_.RoomProblem(false);
  if (!error->empty()) return false;
  const EntityRef e = entities_.AddObstacle(def);
  *added = {static_cast<int>(e.kind), e.serial};
  return true;
}

bool StoreWorld::Add(const ArgosLight& light, ArgosRef* added, std::string* error) {
  LightDef def;
  def.id = light.id;
  def.position = Vec3(light.position[0], light.position[1], light.position[2]);
  def.color = ToColor(light.color), def.intensity = light.intensity, def.medium = light.medium;
  if (entities_.HasId(def.id)) *error = "id '" + def.id + "' is already used";
  if (error->empty() && !(def.intensity >= 0)) *error = "intensity must be >= 0";
  if (error->empty() && !def.medium.empty()) *error = MediumProblem(def.medium);
  if (error->empty()) *error = entities_.RoomProblem(false);
  if (!error->empty()) return false;
  const EntityRef e = entities_.AddLight(def);
  *added = {static_cast<int>(e.kind), e.serial};
  return true;
}

bool StoreWorld::Add(const ArgosRobot& robot, ArgosRef* added, std::string* error) {
  RobotDef def;
  def.id = robot.id;
  def.controller_id = robot.controller_id;
  def.pose = {robot.pose.x, robot.pose.y, robot.pose.yaw};
  def.z = robot.pose.z;
  def.rab_range = robot.rab_range;
  def.camera_aperture = robot.camera_aperture;
  def.loc.element = "AddEntity";
  if (robot.rab_data_size > 65536) {
    *error = "rab_data_size out of range";
    return false;
  }
  def.rab_data_size = static_cast<int>(robot.rab_data_size);
  EntityRef e;
  if (!entities_.AddRobot(def, &e, error)) return false;
  *added = {static_cast<int>(e.kind), e.serial};
  return true;
}

// A controller stopped by an error keeps its state, as ARGoS's does: its globals stay readable.
lua_State* StoreWorld::LuaState(uint32_t robot) {
  if (robot >= controllers_.size() || !controllers_[robot]) return nullptr;
  return LuaStateOf(controllers_[robot].get());
}

std::string& StoreWorld::LogBuffer() {
  ArgosTakeOrphanLog(&log_);
  return log_;
}

void StoreWorld::Log(bool error, const std::string& line) {
  log_ += error ? 'E' : 'O';
  log_ += line;
  log_ += '\n';
}

}  // namespace essaim
