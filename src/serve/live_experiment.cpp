#include "serve/live_experiment.h"

#include <algorithm>
#include <cmath>

#include "core/error_list.h"
#include "core/strings.h"
#include "core/value_json.h"
#include "lua/loop/lua_inspect.h"
#include "output/recording.h"
#include "serve/experiment_inputs.h"
#include "serve/sensor_readings.h"

namespace essaim {

namespace {
// Rounded to `digits` decimals (dividing by a power of ten gives the shortest decimal text).
double Round(double v, int digits) {
  const double scale = std::pow(10.0, digits);
  return std::isfinite(v) ? std::round(v * scale) / scale : 0.0;
}
// Physics keeps the turns a body made; a page wants the heading, in (-pi, pi].
double Heading(double yaw) { return std::isfinite(yaw) ? std::remainder(yaw, 2 * M_PI) : 0.0; }

Value Integer(int64_t i) { return Value::OfInteger(i); }
Value Number(double d) { return Value::OfNumber(d); }
Value Text(std::string s) { return Value::OfString(std::move(s)); }

Value Rgb(const Color& c) {
  Value v = Value::EmptyList();
  v.list = {Integer(c.r), Integer(c.g), Integer(c.b)};
  return v;
}

Value LedOrNull(const Color& c) { return c.IsBlack() ? Value() : Rgb(c); }

Value RobotValue(const World& w, size_t i) {
  const RobotState& r = w.robots[i];
  Pose2 pose = w.physics.RobotPose(static_cast<int>(i));
  Value j = Value::EmptyMap();
  j.Set("id", Text(w.model.robots[i].id));
  j.Set("x", Number(Round(pose.x, 4)));
  j.Set("y", Number(Round(pose.y, 4)));
  j.Set("yaw", Number(Round(Heading(pose.yaw), 4)));
  j.Set("led", LedOrNull(RepresentativeColor(r.leds, footbot::kLedCount)));
  j.Set("alive", Value::OfBool(r.alive));
  j.Set("ok", Value::OfBool(r.controller_ok));
  return j;
}

Value MovableValue(const World& w) {
  Value movable = Value::EmptyList();
  for (size_t k = 0; k < w.model.obstacles.size(); ++k) {
    const ObstacleDef& o = w.model.obstacles[k];
    if (!o.movable) continue;
    Pose2 p = w.physics.ObstaclePose(static_cast<int>(k));
    Value one = Value::EmptyList();
    one.list = {Value::OfUnsigned(k), Number(Round(p.x, 4)), Number(Round(p.y, 4)), Number(Round(Heading(p.yaw), 4)),
                LedOrNull(ObstacleLed(o))};
    movable.list.push_back(std::move(one));
  }
  return movable;
}

Value FrameValue(const World& w, const FrameInfo& info) {
  Value f = Value::EmptyMap();
  f.Set("tick", Value::OfUnsigned(w.tick));
  f.Set("run", Value::OfUnsigned(info.run));
  f.Set("paused", Value::OfBool(info.paused));
  f.Set("speed", Number(info.speed));
  f.Set("error", Text(info.error));
  Value robots = Value::EmptyList();
  robots.list.reserve(w.robots.size());
  for (size_t i = 0; i < w.robots.size(); ++i) robots.list.push_back(RobotValue(w, i));
  f.Set("robots", std::move(robots));
  f.Set("movable", MovableValue(w));
  f.Set("obstacles", Value::OfUnsigned(w.model.obstacles.size()));
  f.Set("series_rows", Value::OfUnsigned(info.series_rows));
  f.Set("log_lines", Value::OfUnsigned(info.log_lines));
  f.Set("scene", Value::OfUnsigned(info.scene));
  if (!info.debug.IsNull()) f.Set("debug", info.debug);
  return f;
}

Value ObstacleValue(const RecordedObstacle& o) {
  Value v = Value::EmptyMap();
  v.Set("id", Text(o.id));
  v.Set("cylinder", Value::OfBool(o.cylinder));
  v.Set("movable", Value::OfBool(o.movable));
  v.Set("x", Number(o.pose.x));
  v.Set("y", Number(o.pose.y));
  v.Set("yaw", Number(o.pose.yaw));
  v.Set("sx", Number(o.size_x));
  v.Set("sy", Number(o.size_y));
  v.Set("r", Number(o.radius));
  v.Set("led", LedOrNull(o.led));
  return v;
}

Value LightValue(const RecordedLight& l) {
  Value v = Value::EmptyMap();
  v.Set("id", Text(l.id));
  v.Set("x", Number(l.position.x()));
  v.Set("y", Number(l.position.y()));
  v.Set("r", Integer(l.color.r));
  v.Set("g", Integer(l.color.g));
  v.Set("b", Integer(l.color.b));
  v.Set("intensity", Number(l.intensity));
  return v;
}

Value SceneValue(const World& w) {
  RecordingScene s = SceneOf(w, 1);
  Value j = Value::EmptyMap();
  j.Set("experiment", Text(s.experiment));
  j.Set("seed", Value::OfUnsigned(s.seed));
  j.Set("tps", Integer(s.ticks_per_second));
  j.Set("length", Integer(s.length_ticks));
  j.Set("minX", Number(s.arena_min.x()));
  j.Set("minY", Number(s.arena_min.y()));
  j.Set("sizeX", Number(s.arena_size.x()));
  j.Set("sizeY", Number(s.arena_size.y()));
  j.Set("radius", Number(s.robot_radius));
  Value ids = Value::EmptyList();
  for (const std::string& id : s.robot_ids) ids.list.push_back(Text(id));
  j.Set("ids", std::move(ids));
  Value obstacles = Value::EmptyList();
  for (const RecordedObstacle& o : s.obstacles) obstacles.list.push_back(ObstacleValue(o));
  j.Set("obstacles", std::move(obstacles));
  Value lights = Value::EmptyList();
  for (const RecordedLight& l : s.lights) lights.list.push_back(LightValue(l));
  j.Set("lights", std::move(lights));
  j.Set("floor", Text(s.floor_png.empty() ? std::string() : Base64Encode(s.floor_png)));
  return j;
}
}  // namespace

std::string FrameText(const World& world, const FrameInfo& info) { return ValueJsonLine(FrameValue(world, info)); }

std::string SceneText(const World& world) { return ValueJsonLine(SceneValue(world)); }

LiveExperiment::LiveExperiment(std::string file, LoadOptions load, LogSink log_sink, Watchdog* watchdog)
    : file_(std::move(file)), load_(std::move(load)), log_sink_(std::move(log_sink)), watchdog_(watchdog) {}

LiveExperiment::~LiveExperiment() = default;

uint64_t LiveExperiment::seed() const { return model_ ? model_->experiment.seed : 0; }

bool LiveExperiment::Load() {
  ErrorList errors;
  std::unique_ptr<Model> model = LoadExperimentFile(file_, load_, &errors);
  std::string error;
  std::unique_ptr<World> world;
  if (model) {
    SimOptions opt;
    opt.output_dir = "";
    opt.log_sink = log_sink_;
    opt.lua.watchdog = watchdog_;
    world = World::Create(*model, opt, &error);
  } else {
    error = errors.Format();
  }
  while (!error.empty() && error.back() == '\n') error.pop_back();
  if (!world) {
    error_ = error.empty() ? "the experiment did not load" : error;
    if (model)  // a script it names now (a new controller file) is watched too
      for (const std::string& f : ExperimentInputs(*model, nullptr))
        if (std::find(inputs_.begin(), inputs_.end(), f) == inputs_.end()) inputs_.push_back(f);
    return false;
  }
  model_ = std::move(model);
  world_ = std::move(world);
  error_ = world_->failure;  // init() failed: shown, the world is not stepped
  ++run_;
  inputs_ = ExperimentInputs(*model_, world_.get());
  return true;
}

bool LiveExperiment::Reset(std::optional<uint64_t> seed) {
  if (seed) load_.seed = seed;
  return Load();
}

StepStatus LiveExperiment::Step() {
  if (!world_ || !world_->failure.empty()) return StepStatus::Failed;
  if (LengthReached(*world_)) return StepStatus::Finished;
  StepStatus status = essaim::Step(*world_);
  if (status == StepStatus::Failed) error_ = world_->failure;
  return status;
}

std::vector<std::string> LiveExperiment::InputFiles() const {
  std::vector<std::string> files = inputs_;
  if (std::find(files.begin(), files.end(), file_) == files.end()) files.push_back(file_);
  return files;
}

namespace {
Value PairValue(const char* a, Value va, const char* b, Value vb) {
  Value v = Value::EmptyMap();
  v.Set(a, std::move(va));
  v.Set(b, std::move(vb));
  return v;
}

Value ActuatorsValue(const RobotState& r) {
  Value wheels = Value::EmptyList();
  wheels.list = {Value::OfNumber(r.wheel_left), Value::OfNumber(r.wheel_right)};
  Value leds = Value::EmptyList();
  for (const Color& c : r.leds) leds.list.push_back(Rgb(c));
  return PairValue("wheels_m_per_s", std::move(wheels), "leds", std::move(leds));
}
}  // namespace

Value LiveExperiment::Inspect(int robot) const {
  if (!world_ || robot < 0 || static_cast<size_t>(robot) >= world_->robots.size()) return Value();
  const World& w = *world_;
  const RobotState& r = w.robots[robot];
  const RobotDef& def = w.model.robots[robot];
  Pose2 pose = w.physics.RobotPose(robot);
  Value j = Value::EmptyMap();
  j.Set("index", Value::OfInteger(robot));
  j.Set("id", Value::OfString(def.id));
  Value where = PairValue("x", Value::OfNumber(pose.x), "y", Value::OfNumber(pose.y));
  where.Set("yaw_deg", Value::OfNumber(Heading(pose.yaw) * 180 / M_PI));
  j.Set("pose", std::move(where));
  j.Set("alive", Value::OfBool(r.alive));
  j.Set("controller_ok", Value::OfBool(r.controller_ok));
  j.Set("battery", Value::OfNumber(def.battery.full_charge > 0 ? r.battery.charge / def.battery.full_charge : 0.0));
  j.Set("actuators", ActuatorsValue(r));
  const ControllerDef* c = def.controller >= 0 ? &w.model.controllers[def.controller] : nullptr;
  if (c) j.Set("controller", ControllerKindValue(*c));
  // A C++ controller has no Lua state: its sensors' readings come from the robot's state.
  const bool cpp = c && c->Cpp();
  lua_State* L = cpp ? nullptr : LuaStateOf(w.controllers[robot].get());
  j.Set("readings", cpp ? SensorReadingsValue(*c, r) : LuaGlobalTree(L, "robot"));
  j.Set("globals", LuaGlobalsTree(L));
  return j;
}

}  // namespace essaim
