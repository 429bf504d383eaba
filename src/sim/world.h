// The World: everything that changes during a run (MuJoCo's mjData), built from a const
// Model. Steps take the World; reset rebuilds it from the Model.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "argos/argos_host.h"
#include "argos/cpp_loop_functions.h"
#include "core/input_files.h"
#include "devices/entity_store.h"
#include "devices/floor.h"
#include "devices/media.h"
#include "devices/robot_state.h"
#include "lua/host/compiled_scripts.h"
#include "lua/host/watchdog.h"
#include "lua/loop/loop_functions.h"
#include "lua/robot/lua_controller.h"
#include "model/model.h"
#include "physics/physics_world.h"

namespace essaim {

/// Seconds spent per stage, summed over the run.
struct StageTimes {
  double act = 0, physics = 0, media = 0, loop_functions = 0, sense = 0, control = 0;
  double Total() const { return act + physics + media + loop_functions + sense + control; }
};

/// Seconds the run took to set up (summary.json's setup_seconds): the model's load (less
/// placement) and placement, then the World's parts in the order they are made.
struct SetupTimes {
  double load = 0, placement = 0;
  double world = 0;       // physics bodies, robot states and devices, media, threads
  double lua_states = 0;  // loop functions' and controllers' states made, scripts run
  double init = 0;        // controllers' and loop functions' init() (then a loop-function floor drawn)
  double Total() const { return load + placement + world + lua_states + init; }
};

struct ControllerError {
  std::string robot;
  uint64_t tick = 0;
  std::string message;
};

/// Where a log line comes from: the tick it was written in (0: during init) and the robot's
/// index into model.robots, or kLogLoopFunctions, or kLogHost (essaim's own messages, such
/// as grouped controller errors).
struct LogOrigin {
  uint64_t tick = 0;
  int robot = -1;
  /// The robot's id (valid during the call; null when `robot` < 0): robots the loop
  /// functions add are named before a printer made from the model knows them.
  const char* robot_id = nullptr;
};
constexpr int kLogLoopFunctions = -1;
constexpr int kLogHost = -2;

struct SimOptions {
  LuaOptions lua;
  std::string output_dir;  // given to the loop functions
  bool strict = false;     // first controller error ends the run
  int threads = -1;        // -1: the model's <system threads>
  /// Receives log()/logerr() lines in robot order ('O' stdout, 'E' stderr, 'P' print) with
  /// who wrote them. Null: dropped.
  std::function<void(char stream, const std::string& line, const LogOrigin& from)> log_sink;
  /// Where the files the run reads are listed; null: the World makes its own. Given by a
  /// caller that must still list them when the World cannot be made (a module that fails).
  std::shared_ptr<InputFiles> inputs;
};

/// The files a model names: the .argos file, the scripts of the controllers robots use,
/// the loop functions, the floor image.
void ListModelInputs(const Model& model, InputFiles* inputs);

/// A parameter given in the XML or by --set that nothing read during the run.
struct UnreadParam {
  std::string path;  // as --set names it: controllers.<id>.params.<key>, loop_functions.<key>
  std::string key;
  std::string did_you_mean;  // the closest key that was read, or ""
  std::string script;        // the script that never read it
  std::string set_by;        // the --set that gave it, or ""
  SourceLoc loc;             // the <lua_controller> or <loop_functions> element
};

class ThreadPool;

class World {
 public:
  /// Builds physics, robot states, Lua controllers (running their init()) and loop
  /// functions (running theirs). Returns nullptr with `error` when a script fails to load,
  /// or C++ loop functions' Init() finds their .argos element bad (bad input). A runtime error in the loop functions'
  /// init(), or in a controller's under `strict`, returns the World with `failure` set: it must not be stepped.
  static std::unique_ptr<World> Create(const Model& model, const SimOptions& options, std::string* error);
  ~World();

  /// The model as this run has it now: a copy that loop functions edit through `entities`
  /// (boxes, cylinders and lights added, removed, moved, recoloured).
  Model scene;
  /// What every stage reads: the scene, const.
  const Model& model;
  SimOptions options;
  /// The watchdog of this World's Lua states when options.lua gave none; declared before
  /// the states, so that it outlives them.
  std::unique_ptr<Watchdog> own_watchdog;
  uint64_t tick = 0;
  /// Robots stepped, summed over the ticks (robots added during the run count from then).
  uint64_t robot_steps = 0;
  /// Every file the run read, modules loaded by `require` included. Before the Lua states,
  /// whose `require` adds to it, so that it outlives them.
  std::shared_ptr<InputFiles> inputs;
  /// The controllers' scripts, compiled once for all their robots.
  CompiledScripts scripts;
  PhysicsWorld physics;
  EntityStore entities;
  RobotStates robots;
  /// The ARGoS side (libraries, session), when the model names C++ loop functions or
  /// controllers; before both, so that it outlives them.
  ArgosHost argos;
  std::vector<std::unique_ptr<RobotController>> controllers;
  LoopFunctions loop_functions;
  /// C++ loop functions (<loop_functions library/label>), when the model names them.
  CppLoopFunctions cpp_loop_functions;
  /// Makes the controllers of foot-bots the loop functions add (sim/robot_joining.h), once
  /// the .argos file's robots have theirs.
  std::unique_ptr<RobotJoiner> robot_joiner;
  Media media;
  FloorRaster floor;
  StageTimes times;
  SetupTimes setup;
  std::vector<ControllerError> controller_errors;
  /// Filled when the run ends (EndRun), or by `essaim check`: see FindUnreadParams.
  std::vector<UnreadParam> unread_params;
  std::string failure;  // set when the run must stop (strict, loop-function error)
  bool finished_by_loop_functions = false;
  int threads = 1;
  std::unique_ptr<ThreadPool> pool;
  /// Per-robot error text of the current tick (written by the robot's own thread).
  std::vector<std::string> pending_errors;
  /// Stage time of each parallel range, indexed by its first robot (no shared writes).
  struct ChunkTimes {
    double sense = 0, control = 0;
  };
  std::vector<ChunkTimes> chunk_times;

 private:
  World(const Model& m, const SimOptions& o);
};

/// robot.params keys (per controller, over all its robots) and experiment.params attributes
/// that no script read so far; `script` itself is never listed. Main thread, between steps.
std::vector<UnreadParam> FindUnreadParams(const World& w);

/// Hands a Lua state's buffered log lines to options.log_sink (from robot index `robot`, or
/// kLogLoopFunctions) and empties the buffer.
void FlushLog(World& w, std::string& buffer, int robot);

}  // namespace essaim
