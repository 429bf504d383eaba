#include "sim/world.h"

#include <algorithm>

#include "argos/cpp_controller.h"
#include "core/rng.h"
#include "core/stopwatch.h"
#include "devices/devices.h"
#include "sim/error_groups.h"
#include "sim/loop_hooks.h"
#include "sim/robot_joining.h"
#include "sim/stepping.h"
#include "sim/thread_pool.h"

namespace essaim {

World::World(const Model& m, const SimOptions& o) : scene(m), model(scene), options(o), physics(scene) {
  entities.Init(&scene, &physics, &robots);
}
World::~World() {
  // Closing a state frees every block it holds (lua_close: ~16 µs a robot, 1.6 s at 100 000
  // robots): on the pool, each thread closing its own range. Nothing else reads a
  // controller by then, and the loop functions' state keeps no reference into theirs.
  if (!pool) return;
  // C++ controllers first, one at a time in robot order: their destructors are user code
  // that ARGoS runs on one thread, and they share the experiment's session.
  for (auto& c : controllers)
    if (dynamic_cast<CppController*>(c.get())) c.reset();
  auto close = [this](int begin, int end) {
    for (int i = begin; i < end; ++i) controllers[i].reset();
  };
  pool->ParallelForBalanced(static_cast<int>(controllers.size()), close);
}

namespace {
bool BuildFloor(World& w, std::string* error) {
  const Model& m = w.model;
  FloorRaster& f = w.floor;
  f.min = m.arena.Min();
  f.size = Vec2(m.arena.size.x(), m.arena.size.y());
  if (m.floor.source == FloorSource::Image) {
    f.width = m.floor.width;
    f.height = m.floor.height;
    f.pixels = m.floor.pixels;
  } else if (m.floor.source == FloorSource::LoopFunctions) {
    if (!w.cpp_loop_functions.Loaded() && !w.loop_functions.HasFunction("floor_color")) {
      *error =
          m.loop_functions.script + ": the floor comes from the loop functions but they define no floor_color(x, y)";
      return false;
    }
    // Sampled at pixel centres: ground sensors then read a raster, thread-safe and fast.
    // Drawn after the loop functions' init() (DrawFloorAfterInit), again after SetChanged().
    f.width = std::max(1, static_cast<int>(m.arena.size.x() * m.floor.pixels_per_meter));
    f.height = std::max(1, static_cast<int>(m.arena.size.y() * m.floor.pixels_per_meter));
    f.pixels.resize(static_cast<size_t>(f.width) * f.height);
  }
  return true;
}

// ARGoS asks GetFloorColor once the loop functions' Init() has run, so a floor drawn from
// what Init() read (zones, food) shows from the first tick on.
bool DrawFloorAfterInit(World& w, std::string* error) {
  if (w.model.floor.source != FloorSource::LoopFunctions) return true;
  TakeFloorChanged(w);  // drawn now: a SetChanged() from Init() asks for nothing more
  return DrawLoopFloor(w, error);
}

// A controller with no step() after init() would stand still all run: the run fails
// instead (ARGoS logs it once per robot and goes on). Checked after init(), which may
// define step().
std::string MissingStep(World& w) {
  std::string first;
  size_t count = 0;
  for (size_t i = 0; i < w.controllers.size(); ++i) {
    const std::string& script = w.model.controllers[w.model.robots[i].controller].script;
    if (script.empty() || !w.robots[i].controller_ok || w.controllers[i]->HasStep()) continue;
    if (count++ == 0) first = "robot " + w.model.robots[i].id + ": " + script;
  }
  if (count == 0) return {};
  return first + ": no global function 'step' after init()" +
         (count > 1 ? " (nor in " + std::to_string(count - 1) + " more robots)" : "") +
         "; a controller defines init() and step()";
}
}  // namespace

namespace {
bool IsCpp(const World& w, int robot) {
  const int c = w.model.robots[robot].controller;
  return c >= 0 && w.model.controllers[c].Cpp();
}

// Robot states, sized once and filled in place: each robot's random streams, its devices
// (bodies in the physics world), then the media's buffers and the thread pool.
void MakeRobots(World& w, const SimOptions& options) {
  const Model& model = w.model;
  const size_t n = model.robots.size();
  w.robots.resize(n);
  w.pending_errors.resize(n);
  w.chunk_times.resize(n + 1);
  for (size_t i = 0; i < n; ++i) InitRobotState(model, static_cast<int>(i), w.robots[i], w.physics);
  InitMedia(model, &w.media);  // buffers sized once, by who is in which medium
  w.threads = options.threads >= 0 ? options.threads : model.experiment.threads;
  if (w.threads < 1) w.threads = 1;
  w.pool = std::make_unique<ThreadPool>(w.threads);
}

// One Lua state per robot, its top-level chunk run, on the pool: the states share nothing
// (the compiled scripts and the input list lock), and each thread writes only its own
// robots' slots. C++ controllers after, one at a time in robot order, as ARGoS makes them
// (what their constructors draw from CRandom's "argos" category depends on that order). A
// failure reports the lowest robot index's error, as a serial loop would.
bool MakeControllerStates(World& w, std::string* error) {
  const size_t n = w.model.robots.size();
  w.controllers.resize(n);
  std::vector<char> failed(n, 0);
  auto make = [&](int begin, int end) {
    for (int i = begin; i < end; ++i) {
      if (IsCpp(w, i)) continue;
      auto lua = std::make_unique<LuaController>();
      failed[i] = !lua->Load(w.model, w.model.robots[i], &w.robots[i], w.model.experiment.seed, w.options.lua,
                             &w.pending_errors[i]);
      w.controllers[i] = std::move(lua);
    }
  };
  w.pool->ParallelForBalanced(static_cast<int>(n), make);
  for (int i = 0; i < static_cast<int>(n); ++i) {
    if (!IsCpp(w, i)) continue;
    const SteppingScope stepping(i, "constructor");
    w.controllers[i] = CppController::Make(w.model, i, &w.robots[i], &w.argos, &w.pending_errors[i]);
    failed[i] = !w.controllers[i];
  }
  const auto first = std::find(failed.begin(), failed.end(), 1);
  if (first != failed.end()) *error = w.pending_errors[static_cast<size_t>(first - failed.begin())];
  for (std::string& e : w.pending_errors) e.clear();
  return first == failed.end();
}

// The loop functions' state (first: its script defines floor_color), then the
// controllers'; false with `error` when a script fails.
bool MakeLuaStates(World& w, std::string* error) {
  if (ArgosHost::Needed(w.model) && !w.argos.Load(w.model, &w.entities, &w.controllers, error)) return false;
  if (w.model.loop_functions.Cpp()) {
    if (!w.cpp_loop_functions.Load(w.model, &w.argos, error)) return false;
  } else {
    w.loop_functions.SetLimits(w.options.lua);
    if (!w.loop_functions.Load(w.model, &w.entities, &w.controllers, w.options.output_dir, error)) return false;
  }
  if (!BuildFloor(w, error)) return false;
  if (!MakeControllerStates(w, error)) return false;
  w.robot_joiner = std::make_unique<WorldRobotJoiner>(w);
  w.entities.SetRobotJoiner(w.robot_joiner.get());
  return true;
}

// A C++ controller's Init that threw a configuration error (a bad <params>, GetSensor of a
// device its entry does not declare): bad input, as the loop functions' (World::Create).
bool InitConfigurationError(World& w, int i) {
  return IsCpp(w, i) && static_cast<CppController&>(*w.controllers[i]).LastErrorIsConfiguration();
}

// Every Lua controller's init() on the pool, then every C++ controller's Init in robot order
// (ARGoS's order, which CRandom's draws depend on), then their errors in robot order. A serial
// loop stops at the first error that ends the run (strict, os.exit, a configuration error):
// the robots after it keep only what their top-level chunk logged, and their errors are not
// reported, as then. True when that error was a configuration error.
bool RunControllerInits(World& w) {
  const size_t n = w.controllers.size();
  std::vector<char> failed(n, 0), bad_input(n, 0);
  std::vector<size_t> logged_before_init(n, 0);
  auto init = [&](int begin, int end) {
    for (int i = begin; i < end; ++i) {
      if (IsCpp(w, i)) continue;
      logged_before_init[i] = w.controllers[i]->LogBuffer().size();
      const SteppingScope stepping(i, "Init");
      failed[i] = !w.controllers[i]->Init(&w.pending_errors[i]);
    }
  };
  w.pool->ParallelForBalanced(static_cast<int>(n), init);
  for (size_t i = 0; i < n; ++i)
    if (IsCpp(w, static_cast<int>(i))) {
      const SteppingScope stepping(static_cast<int>(i), "Init");
      failed[i] = !w.controllers[i]->Init(&w.pending_errors[i]);
      bad_input[i] = failed[i] && InitConfigurationError(w, static_cast<int>(i));
    }
  size_t last = n;  // the robot whose error ends the run, or n
  for (size_t i = 0; i < n && last == n; ++i) {
    if (!failed[i]) continue;
    w.robots[i].controller_ok = false;
    w.controller_errors.push_back({w.model.robots[i].id, 0, w.pending_errors[i]});
    if (w.options.strict || w.controllers[i]->ExitCalled() || bad_input[i]) {
      w.failure = w.pending_errors[i];
      last = i;
    }
  }
  for (size_t i = last + 1; i < n; ++i) w.controllers[i]->LogBuffer().resize(logged_before_init[i]);
  for (std::string& e : w.pending_errors) e.clear();
  return last < n && bad_input[last];
}

// Every controller's init(), then the loop functions'; errors as World::Create says.
// False when the loop functions' init() found their .argos element bad (w.failure says
// where): bad input, not a run that failed.
bool RunInits(World& w) {
  const SimOptions& options = w.options;
  const bool bad_controller_params = RunControllerInits(w);
  for (size_t i = 0; i < w.controllers.size(); ++i) FlushLog(w, w.controllers[i]->LogBuffer(), static_cast<int>(i));
  if (bad_controller_params) return false;
  if (w.failure.empty()) w.failure = MissingStep(w);
  // Printed like step() errors, identical ones grouped.
  if (options.log_sink)
    for (const std::string& text : GroupControllerErrors(w.controller_errors, 0))
      options.log_sink('E', text, {0, kLogHost});
  // A runtime error in init() is the run failing, not bad input: the World is returned
  // with `failure` set, so the caller can still write a summary (exit 1, docs/cli.md).
  std::string err;
  bool bad_input = false;
  if (w.failure.empty() && !CallLoopHook(w, "init", &err)) {
    w.failure = err;
    bad_input = w.cpp_loop_functions.Loaded() && w.cpp_loop_functions.LastErrorIsConfiguration();
  }
  if (w.failure.empty() && !DrawFloorAfterInit(w, &err)) w.failure = err;
  FlushLoopLog(w);
  return !bad_input;
}
}  // namespace

std::unique_ptr<World> World::Create(const Model& source, const SimOptions& options, std::string* error) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  std::unique_ptr<World> w(new World(source, options));
  w->setup.load = source.load_seconds.total - source.load_seconds.placement;
  w->setup.placement = source.load_seconds.placement;
  MakeRobots(*w, options);
  w->inputs = options.inputs ? options.inputs : std::make_shared<InputFiles>();
  ListModelInputs(w->model, w->inputs.get());
  w->options.lua.inputs = w->inputs.get();
  if (!w->options.lua.scripts) w->options.lua.scripts = &w->scripts;
  if (!w->options.lua.watchdog) {
    w->own_watchdog = std::make_unique<Watchdog>();
    w->options.lua.watchdog = w->own_watchdog.get();
  }
  w->setup.world = SecondsSince(start);
  const Clock::time_point lua_start = Clock::now();
  if (!MakeLuaStates(*w, error)) return nullptr;
  w->setup.lua_states = SecondsSince(lua_start);
  const Clock::time_point init_start = Clock::now();
  if (!RunInits(*w)) {
    *error = w->failure;
    return nullptr;
  }
  w->setup.init = SecondsSince(init_start);
  return w;
}

void ListModelInputs(const Model& model, InputFiles* inputs) {
  inputs->Add(model.file, "arena");
  std::vector<bool> used(model.controllers.size(), false);
  for (const RobotDef& r : model.robots)
    if (r.controller >= 0) used[static_cast<size_t>(r.controller)] = true;
  for (size_t i = 0; i < model.controllers.size(); ++i)
    if (used[i] && !model.controllers[i].script.empty()) inputs->Add(model.controllers[i].script, "controller");
  // Every C++ controller's library is loaded, used or not (as ARGoS): its bytes make the run.
  for (const ControllerDef& c : model.controllers)
    if (!c.library.empty()) inputs->Add(c.library, "controller_library");
  if (!model.loop_functions.script.empty()) inputs->Add(model.loop_functions.script, "loop_functions");
  if (!model.loop_functions.library.empty()) inputs->Add(model.loop_functions.library, "loop_functions_library");
  if (model.floor.source == FloorSource::Image) inputs->Add(model.floor.path, "floor_image");
}

void FlushLog(World& w, std::string& buffer, int robot) {
  if (buffer.empty()) return;
  if (w.options.log_sink) {
    // Each line is "<stream char><text>\n" (lua_state.cpp's log/logerr/print).
    const LogOrigin from{w.tick, robot, robot >= 0 ? w.model.robots[robot].id.c_str() : nullptr};
    size_t start = 0;
    while (start < buffer.size()) {
      size_t end = buffer.find('\n', start);
      if (end == std::string::npos) end = buffer.size();
      w.options.log_sink(buffer[start], buffer.substr(start + 1, end - start - 1), from);
      start = end + 1;
    }
  }
  buffer.clear();  // keeps capacity: no churn once warm
}

}  // namespace essaim
