#include "serve/live_experiment.h"

#include <algorithm>
#include <cmath>

#include "core/error_list.h"
#include "core/json.h"
#include "core/strings.h"
#include "lua/loop/lua_inspect.h"
#include "output/recording.h"
#include "serve/experiment_inputs.h"

namespace essaim {

namespace {
// Rounded to `digits` decimals (dividing by a power of ten gives the shortest decimal text).
double Round(double v, int digits) {
  const double scale = std::pow(10.0, digits);
  return std::isfinite(v) ? std::round(v * scale) / scale : 0.0;
}
// Physics keeps the turns a body made; a page wants the heading, in (-pi, pi].
double Heading(double yaw) { return std::isfinite(yaw) ? std::remainder(yaw, 2 * M_PI) : 0.0; }

Json Rgb(const Color& c) { return Json::array({c.r, c.g, c.b}); }

Json LedOrNull(const Color& c) { return c.IsBlack() ? Json() : Rgb(c); }

Json RobotJson(const World& w, size_t i) {
  const RobotState& r = w.robots[i];
  Pose2 pose = w.physics.RobotPose(static_cast<int>(i));
  Json j = Json::object();
  j["id"] = w.model.robots[i].id;
  j["x"] = Round(pose.x, 4);
  j["y"] = Round(pose.y, 4);
  j["yaw"] = Round(Heading(pose.yaw), 4);
  j["led"] = LedOrNull(RepresentativeColor(r.leds, footbot::kLedCount));
  j["alive"] = r.alive;
  j["ok"] = r.controller_ok;
  return j;
}
}  // namespace

namespace {
Json FrameJson(const World& w, const FrameInfo& info) {
  Json f = Json::object();
  f["tick"] = w.tick;
  f["run"] = info.run;
  f["paused"] = info.paused;
  f["speed"] = info.speed;
  f["error"] = info.error;
  Json robots = Json::array();
  for (size_t i = 0; i < w.robots.size(); ++i) robots.push_back(RobotJson(w, i));
  f["robots"] = std::move(robots);
  Json movable = Json::array();
  for (size_t k = 0; k < w.model.obstacles.size(); ++k) {
    const ObstacleDef& o = w.model.obstacles[k];
    if (!o.movable) continue;
    Pose2 p = w.physics.ObstaclePose(static_cast<int>(k));
    movable.push_back(
        Json::array({k, Round(p.x, 4), Round(p.y, 4), Round(Heading(p.yaw), 4), LedOrNull(ObstacleLed(o))}));
  }
  f["movable"] = std::move(movable);
  f["obstacles"] = w.model.obstacles.size();
  f["series_rows"] = info.series_rows;
  f["log_lines"] = info.log_lines;
  return f;
}

Json SceneJson(const World& w) {
  RecordingScene s = SceneOf(w, 1);
  Json j = Json::object();
  j["experiment"] = s.experiment;
  j["seed"] = s.seed;
  j["tps"] = s.ticks_per_second;
  j["length"] = s.length_ticks;
  j["minX"] = s.arena_min.x();
  j["minY"] = s.arena_min.y();
  j["sizeX"] = s.arena_size.x();
  j["sizeY"] = s.arena_size.y();
  j["radius"] = s.robot_radius;
  j["ids"] = s.robot_ids;
  Json obstacles = Json::array();
  for (const RecordedObstacle& o : s.obstacles)
    obstacles.push_back({{"id", o.id},
                         {"cylinder", o.cylinder},
                         {"movable", o.movable},
                         {"x", o.pose.x},
                         {"y", o.pose.y},
                         {"yaw", o.pose.yaw},
                         {"sx", o.size_x},
                         {"sy", o.size_y},
                         {"r", o.radius},
                         {"led", LedOrNull(o.led)}});
  j["obstacles"] = std::move(obstacles);
  Json lights = Json::array();
  for (const RecordedLight& l : s.lights)
    lights.push_back({{"id", l.id},
                      {"x", l.position.x()},
                      {"y", l.position.y()},
                      {"r", l.color.r},
                      {"g", l.color.g},
                      {"b", l.color.b},
                      {"intensity", l.intensity}});
  j["lights"] = std::move(lights);
  j["floor"] = s.floor_png.empty() ? std::string() : Base64Encode(s.floor_png);
  return j;
}
}  // namespace

std::string FrameText(const World& world, const FrameInfo& info) { return DumpJsonLine(FrameJson(world, info)); }

std::string SceneText(const World& world) { return DumpJsonLine(SceneJson(world)); }

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
Value RgbValue(const Color& c) {
  Value v = Value::EmptyList();
  for (unsigned char part : {c.r, c.g, c.b}) v.list.push_back(Value::OfInteger(part));
  return v;
}

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
  for (const Color& c : r.leds) leds.list.push_back(RgbValue(c));
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
  lua_State* L = w.controllers[robot] ? w.controllers[robot]->State() : nullptr;
  j.Set("readings", LuaGlobalTree(L, "robot"));
  j.Set("globals", LuaGlobalsTree(L));
  return j;
}

}  // namespace essaim
