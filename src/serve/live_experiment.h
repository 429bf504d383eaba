// The experiment a live view shows: loaded, reloaded on save, reset and stepped, always on
// one thread (the simulation's). What the page and /api/state see of it is JSON built here.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/value.h"
#include "model/xml_loader.h"
#include "sim/step.h"

namespace essaim {

class Watchdog;

using LogSink = std::function<void(char stream, const std::string& line, const LogOrigin& from)>;

/// What a frame says besides the world itself.
struct FrameInfo {
  uint64_t run = 0;
  bool paused = true;
  double speed = 1;  // multiple of real time; 0: as fast as it goes
  std::string error;
  size_t series_rows = 0;
  uint64_t log_lines = 0;
  uint64_t scene = 0;  // the version of /api/scene: a page fetches it again when it changes
  /// `essaim debug --serve`'s {paused, tick, boundary, thread, selected, robot, robot_index,
  /// ended}; null: none.
  Value debug;
};

/// One frame: {tick, run, paused, speed, error, robots: [{id, x, y, yaw, led, alive, ok}],
/// movable: [[obstacle index, x, y, yaw, led]] (movable obstacles only), series_rows, log_lines, scene,
/// debug (when set)}. Positions are
/// rounded to 0.1 mm and yaws to 1e-4 rad (a page needs no more; frames stay small). JSON
/// text on one line.
std::string FrameText(const World& world, const FrameInfo& info);
/// What does not change between frames: the arena, obstacles, lights, the floor (a PNG in
/// base64), robot ids. Field names as the replay page's scene. JSON text on one line.
std::string SceneText(const World& world);

class LiveExperiment {
 public:
  LiveExperiment(std::string file, LoadOptions load, LogSink log_sink, Watchdog* watchdog = nullptr);
  ~LiveExperiment();

  /// Reads the files again and builds a fresh world (run + 1). On failure the last good
  /// world stays, Error() gives the reason (file:line) and false is returned.
  bool Load();
  /// A fresh world from the same files (run + 1); with `seed`, that seed from now on.
  bool Reset(std::optional<uint64_t> seed);
  /// One tick; Finished or Failed pause the page (the caller's business).
  StepStatus Step();

  World* world() { return world_.get(); }
  const World* world() const { return world_.get(); }
  uint64_t run() const { return run_; }
  uint64_t seed() const;
  /// The last load's error, or the run's failure (a loop-function error); "" when none.
  const std::string& Error() const { return error_; }
  /// Every file the experiment read: the .argos file, controller scripts, loop functions,
  /// floor image, and the modules they `require`d. After a failed load, the last good
  /// list plus the .argos file.
  std::vector<std::string> InputFiles() const;
  /// A robot's inspector: pose, battery, actuators, its `robot` table (readings), its
  /// controller's own globals. Null for an index out of range.
  Value Inspect(int robot) const;

 private:
  std::string file_;
  LoadOptions load_;
  LogSink log_sink_;
  Watchdog* watchdog_;  // null: each World makes its own
  std::unique_ptr<Model> model_;
  std::unique_ptr<World> world_;
  std::vector<std::string> inputs_;
  uint64_t run_ = 0;
  std::string error_;
};

}  // namespace essaim
