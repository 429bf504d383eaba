// Shared by tests and benchmarks: build an experiment from inline XML and Lua text in a
// private temporary folder, then step it.
#pragma once
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "core/error_list.h"
#include "core/hash.h"
#include "model/xml_loader.h"
#include "output/atomic_file.h"
#include "sim/step.h"
#include "sim/world.h"

namespace essaim::testing {

/// A controller that drives on at `speed` cm/s and, with probability `chance` a step, turns
/// by a Gaussian amount (standard deviation `turn`): robots that spread, meet and collide,
/// drawing on their random streams every step. The arguments are Lua number literals.
inline std::string WanderController(const char* chance = "0.1", const char* turn = "5", const char* speed = "15") {
  return std::string("\nfunction step()\n  if robot.random.uniform() < ") + chance +
         " then\n    local turn = robot.random.gaussian(" + turn + ")\n    robot.wheels.set_velocity(" + speed +
         " - turn, " + speed + " + turn)\n  end\nend\n";
}

/// A fresh folder under /tmp, removed at destruction.
class TempDir {
 public:
  TempDir() {
    char tmpl[] = "/tmp/essaim-test-XXXXXX";
    path_ = mkdtemp(tmpl);
  }
  ~TempDir() { std::system(("rm -rf '" + path_ + "'").c_str()); }
  const std::string& path() const { return path_; }
  std::string Write(const std::string& name, const std::string& content) const {
    std::string p = path_ + "/" + name;
    std::string err;
    WriteFileAtomic(p, content, &err);
    return p;
  }

 private:
  std::string path_;
};

/// The usual .argos skeleton around an arena body and a controller.
inline std::string Experiment(const std::string& arena, const std::string& controllers, int ticks = 10, int seed = 1,
                              const std::string& extra = "", int tps = 10) {
  return "<argos-configuration>\n"
         "  <framework><experiment length=\"" +
         std::to_string(ticks / static_cast<double>(tps)) + "\" ticks_per_second=\"" + std::to_string(tps) +
         "\" random_seed=\"" + std::to_string(seed) +
         "\"/></framework>\n"
         "  <controllers>" +
         controllers +
         "</controllers>\n"
         "  <arena size=\"10,10,1\" center=\"0,0,0.5\">" +
         arena +
         "</arena>\n"
         "  <physics_engines><dynamics2d id=\"dyn2d\" iterations=\"10\"/></physics_engines>\n"
         "  <media/>\n" +
         extra + "</argos-configuration>\n";
}

/// A lua_controller with wheels and positioning.
inline std::string WheelsController(const std::string& id, const std::string& script,
                                    const std::string& more_sensors = "", const std::string& params = "") {
  return "<lua_controller id=\"" + id +
         "\"><actuators><differential_steering implementation=\"default\"/></actuators>"
         "<sensors><differential_steering implementation=\"default\"/><positioning implementation=\"default\"/>" +
         more_sensors + "</sensors><params script=\"" + script + "\" " + params + "/></lua_controller>";
}

inline std::string FootBot(const std::string& id, double x, double y, double yaw_deg, const std::string& ctrl) {
  char buf[256];
  std::snprintf(
      buf, sizeof buf,
      "<foot-bot id=\"%s\"><body position=\"%g,%g,0\" orientation=\"%g,0,0\"/><controller config=\"%s\"/></foot-bot>",
      id.c_str(), x, y, yaw_deg, ctrl.c_str());
  return buf;
}

/// A static box of size sx × sy × h (m) with its base centred at (x, y).
inline std::string Box(const std::string& id, double x, double y, double sx, double sy, double h) {
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "<box id=\"%s\" size=\"%.9g,%.9g,%.9g\" movable=\"false\"><body position=\"%.9g,%.9g,0\" "
                "orientation=\"0,0,0\"/></box>",
                id.c_str(), sx, sy, h, x, y);
  return buf;
}

struct Scene {
  std::unique_ptr<Model> model;
  std::unique_ptr<World> world;
  ErrorList errors;
  std::string error;
  bool ok() const { return model && world; }
};

/// Loads `xml` as if it were the file dir/experiment.argos and builds its World.
inline Scene Load(const TempDir& dir, const std::string& xml, LoadOptions opt = {}, SimOptions sim = {}) {
  Scene s;
  std::string path = dir.Write("experiment.argos", xml);
  s.model = LoadExperimentFile(path, opt, &s.errors);
  if (!s.model) {
    s.error = s.errors.Format();
    return s;
  }
  s.world = World::Create(*s.model, sim, &s.error);
  return s;
}

inline void RunTicks(World& w, int ticks) {
  for (int i = 0; i < ticks; ++i) Step(w);
}

/// Hash of every robot's pose: the determinism tests' fingerprint.
inline uint64_t PoseHash(const World& w) {
  Fnv1a64 h;
  for (int i = 0; i < w.physics.RobotCount(); ++i) {
    Pose2 p = w.physics.RobotPose(i);
    h.AddValue(p.x);
    h.AddValue(p.y);
    h.AddValue(p.yaw);
  }
  return h.Value();
}

}  // namespace essaim::testing
