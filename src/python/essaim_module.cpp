// The `essaim` Python module (pybind11; the only file that includes it). A Simulation owns
// its Model and World: no global state, so several run in threads at once; the GIL is
// released while stepping. Runs use the CLI's loader, step and output code (bit-identical
// results, same files in `out`).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/paths.h"
#include "core/stopwatch.h"
#include "core/value_json.h"
#include "lua/host/watchdog.h"
#include "lua/loop/lua_copy.h"
#include "model/xml_loader.h"
#include "output/atomic_file.h"
#include "output/out_folder.h"
#include "output/recording.h"
#include "output/summary.h"
#include "sim/run_end.h"
#include "sim/step.h"
#ifdef ESSAIM_HAVE_CAIRO
#include "render/render_cairo.h"
#endif

namespace py = pybind11;

namespace essaim {
namespace {

// Ticks stepped between two checks for Ctrl-C (needs the GIL back briefly).
constexpr uint64_t kSignalCheckTicks = 256;
// Log lines held before they are handed to Python (stepping pauses for it).
constexpr size_t kMaxHeldLogLines = 10000;

py::object FromJsonText(const std::string& text) {
  // Through Python's json module: the JSON library stays an implementation detail.
  return py::module_::import("json").attr("loads")(text);
}

/// Yaw in (-pi, pi], as numpy users expect angles (Box2D's angle is unbounded).
double WrapYaw(double yaw) {
  double a = std::remainder(yaw, 2 * M_PI);
  return a <= -M_PI ? a + 2 * M_PI : a;
}

/// A one-dimensional array of n items. Shape and strides are given: with pybind11 2.10 and
/// NumPy 2, array_t(count) filled through mutable_unchecked read back the last value
/// written in every item (battery() and alive() gave every robot the last robot's).
template <class T>
py::array_t<T> Vector(size_t n) {
  return py::array_t<T>(std::vector<py::ssize_t>{static_cast<py::ssize_t>(n)},
                        std::vector<py::ssize_t>{static_cast<py::ssize_t>(sizeof(T))});
}

/// A log line waiting for the GIL: the sink runs while stepping, without it.
struct LogLine {
  char stream;
  std::string text;
  LogOrigin from;
};

std::string ValueText(const py::handle& v) {
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::float_>(v)) return py::str(py::repr(v)).cast<std::string>();
  return py::str(v).cast<std::string>();
}

// What the CLI refuses, refused before anything is loaded or created: a thread count out
// of --threads' range (100000 threads hung), a NUL byte in a path (C would cut it there).
constexpr int kMaxThreads = 1024;
void CheckArguments(const std::string& path, std::optional<int> threads, const std::optional<std::string>& out) {
  if (threads && (*threads < 1 || *threads > kMaxThreads))
    throw py::value_error("threads must be between 1 and " + std::to_string(kMaxThreads) + ", got " +
                          std::to_string(*threads) + " (None: the experiment's <system threads>)");
  if (path.find('\0') != std::string::npos) throw py::value_error("path holds a NUL byte");
  if (out && out->find('\0') != std::string::npos) throw py::value_error("out holds a NUL byte");
}

class Simulation {
 public:
  Simulation(const std::string& path, std::optional<uint64_t> seed, std::optional<int> threads,
             std::optional<py::dict> overrides, std::optional<std::string> out, bool strict)
      : path_(path), strict_(strict), out_(out.value_or("")) {
    CheckArguments(path, threads, out);
    load_.strict = strict;
    load_.seed = seed;
    load_.threads = threads;
    if (overrides)
      for (auto item : *overrides)
        load_.overrides.push_back(py::str(item.first).cast<std::string>() + "=" + ValueText(item.second));
    Load();
  }

  /// Starts the run again from tick 0, with `seed` if given (else the same seed): the
  /// experiment file and its scripts are read again, so edits since are taken.
  void Reset(std::optional<uint64_t> seed) {
    if (seed) load_.seed = seed;
    Close();
    status_ = StepStatus::Running;
    finished_ = false;
    metrics_ = summary_ = py::none();
    errors_ = py::list();
    reported_errors_ = 0;
    Load();
  }

  struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
  };

 private:
  void Load() {
    ErrorList errors, warnings;
    model_ = LoadExperimentFile(path_, load_, &errors, &warnings);
    if (!model_) throw Error(errors.Format());
    Warn(warnings);
    std::string error;
    if (!out_.empty() && (!PrepareOutFolder(out_, &error) || (!out_lock_.Held() && !out_lock_.Acquire(out_, &error))))
      throw Error(error);
    t0_ = std::chrono::steady_clock::now();
    {
      py::gil_scoped_release nogil;
      world_ = World::Create(*model_, Options(), &error);
    }
    if (!world_) {
      logs_.clear();  // lines of a World that was not made: its error says what went wrong
      throw Error(error);
    }
    Report();
    if (!world_->failure.empty()) throw Error(world_->failure);  // an init() error
    SetAside();
    if (LengthReached(*world_)) status_ = StepStatus::Finished;
  }

  SimOptions Options() {
    SimOptions opt;
    opt.output_dir = out_;
    opt.strict = strict_;
    opt.lua.memory_limit = 64u << 20;  // the CLI's limits
    opt.lua.instruction_limit = opt.lua.setup_instruction_limit = kDefaultStepBudget;
    opt.lua.watchdog = &watchdog_;
    opt.log_sink = [this](char stream, const std::string& line, const LogOrigin& from) {
      logs_.push_back({stream, line, from});
    };
    return opt;
  }

  // The CLI's warnings (unknown attributes...) as Python warnings, one per line.
  static void Warn(const ErrorList& warnings) {
    for (const InputError& w : warnings.Items()) {
      ErrorList one;
      one.Add(w.file, w.line, w.element, w.message);
      std::string text = one.Format();
      while (!text.empty() && text.back() == '\n') text.pop_back();
      py::module_::import("warnings").attr("warn")(text, py::module_::import("builtins").attr("UserWarning"), 2);
    }
  }

  // As `essaim run`: the folder holds this run's outputs only; an earlier run's are moved.
  void SetAside() {
    std::vector<std::string> moved;
    std::string error;
    if (!out_.empty() && !SetAsideEarlierOutputs(out_, &moved, &error)) throw Error(error);
    if (moved.empty()) return;
    std::string names;
    for (const std::string& name : moved) names += (names.empty() ? "" : ", ") + name;
    py::module_::import("warnings")
        .attr("warn")(out_ + " held an earlier run's outputs; moved them into " + JoinPath(out_, kPreviousRunFolder) +
                      ": " + names);
  }

  /// Hands the log lines and controller errors gathered while stepping to Python: lines to
  /// the `essaim` logger (log/print INFO, logerr WARNING, essaim's error messages ERROR),
  /// errors to `errors`. Called with the GIL held.
  void Report() {
    if (!logs_.empty()) {
      py::object logger = py::module_::import("logging").attr("getLogger")("essaim");
      for (const LogLine& l : logs_) Log(logger, l);
      logs_.clear();
    }
    const auto& all = world_->controller_errors;
    for (; reported_errors_ < all.size(); ++reported_errors_) {
      const ControllerError& e = all[reported_errors_];
      py::dict d;
      d["robot"] = e.robot, d["tick"] = e.tick, d["message"] = e.message;
      errors_.append(d);
    }
  }

  void Log(const py::object& logger, const LogLine& l) const {
    const int level = l.from.robot == kLogHost ? 40 : l.stream == 'E' ? 30 : 20;
    std::string who = l.from.robot >= 0                   ? world_->model.robots[static_cast<size_t>(l.from.robot)].id
                      : l.from.robot == kLogLoopFunctions ? std::string("loop functions")
                                                          : std::string();
    py::dict extra;
    extra["robot"] = l.from.robot >= 0 ? py::object(py::str(who)) : py::object(py::none());
    extra["tick"] = l.from.tick;
    logger.attr("log")(level, "%s", who.empty() ? l.text : who + ": " + l.text, py::arg("extra") = extra);
  }

 public:
  /// Steps up to n ticks (fewer when the experiment ends); returns the ticks stepped.
  uint64_t StepN(uint64_t n) {
    World& w = Live();
    if (finished_) throw Error("step: this run has ended (finish() was called)");
    uint64_t done = 0;
    while (done < n && status_ == StepStatus::Running) {
      uint64_t chunk = std::min<uint64_t>(n - done, kSignalCheckTicks);
      {
        py::gil_scoped_release nogil;
        for (uint64_t i = 0; i < chunk && status_ == StepStatus::Running && logs_.size() < kMaxHeldLogLines;
             ++i, ++done)
          status_ = Step(w);
      }
      Report();
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    }
    if (status_ == StepStatus::Failed) throw Error(FailureText());
    return done;
  }

  uint64_t Run() { return StepN(UINT64_MAX); }

  uint64_t Tick() const { return Live().tick; }
  bool Finished() const { return status_ != StepStatus::Running; }

  py::list RobotIds() const {
    py::list ids;
    for (const RobotDef& r : Robots()) ids.append(r.id);
    return ids;
  }

  py::array_t<double> Poses() const {
    const World& w = Live();
    py::array_t<double> a({static_cast<py::ssize_t>(w.robots.size()), py::ssize_t{3}});
    auto m = a.mutable_unchecked<2>();
    for (size_t i = 0; i < w.robots.size(); ++i) {
      Pose2 p = w.physics.RobotPose(static_cast<int>(i));
      m(i, 0) = p.x, m(i, 1) = p.y, m(i, 2) = WrapYaw(p.yaw);
    }
    return a;
  }

  py::array_t<bool> Alive() const {
    const World& w = Live();
    py::array_t<bool> a = Vector<bool>(w.robots.size());
    auto m = a.mutable_unchecked<1>();
    for (size_t i = 0; i < w.robots.size(); ++i) m(i) = w.robots[i].alive;
    return a;
  }

  /// Charge left as a fraction of the full charge (the battery sensor's available_charge).
  py::array_t<double> Battery() const {
    const World& w = Live();
    py::array_t<double> a = Vector<double>(w.robots.size());
    auto m = a.mutable_unchecked<1>();
    for (size_t i = 0; i < w.robots.size(); ++i) {
      double full = w.model.robots[i].battery.full_charge;
      m(i) = full > 0 ? w.robots[i].battery.charge / full : 0.0;
    }
    return a;
  }

  py::array_t<uint8_t> LedColors() const {
    const World& w = Live();
    py::array_t<uint8_t> a(
        {static_cast<py::ssize_t>(w.robots.size()), py::ssize_t{footbot::kLedCount}, py::ssize_t{3}});
    auto m = a.mutable_unchecked<3>();
    for (size_t i = 0; i < w.robots.size(); ++i)
      for (int k = 0; k < footbot::kLedCount; ++k) {
        const Color& c = w.robots[i].leds[k];
        m(i, k, 0) = c.r, m(i, k, 1) = c.g, m(i, k, 2) = c.b;
      }
    return a;
  }

  /// Ends the run: post_experiment, controllers' destroy, outputs written to `out`.
  /// Returns the metrics (post_experiment's table, {} when it returned none).
  py::object Finish() {
    if (finished_) throw Error("finish: this run has ended already (finish() was called)");
    World& w = Live();
    RunInfo info;
    info.version = ESSAIM_VERSION;
    if (status_ == StepStatus::Running) info.finished_by = "finish";  // stopped before the end
    Value metrics;
    bool has_metrics = false;
    {
      py::gil_scoped_release nogil;
      EndRun(w, status_, &info, &metrics, &has_metrics);
    }
    bool ok = !(info.status == "failed" && status_ != StepStatus::Failed);
    std::string error;
    info.wall_seconds = SecondsSince(t0_);
    finished_ = true;
    Report();
    summary_ = FromJsonText(SummaryJsonText(w, info));
    metrics_ = has_metrics ? FromJsonText(ValueJsonText(metrics)) : py::dict();
    if (!out_.empty() && !WriteRunOutputs(out_, w, info, has_metrics ? &metrics : nullptr, &error)) throw Error(error);
    if (!ok) throw Error(w.failure);
    return metrics_;
  }

  /// summary.json's content; before finish(), the run so far (status "running").
  py::object Summary() const {
    if (finished_) return summary_;
    RunInfo info;
    info.version = ESSAIM_VERSION;
    info.status = status_ == StepStatus::Running ? "running" : status_ == StepStatus::Failed ? "failed" : "ok";
    info.finished_by = status_ == StepStatus::Running ? "" : "not finished: call finish()";
    info.wall_seconds = SecondsSince(t0_);
    return FromJsonText(SummaryJsonText(Live(), info));
  }

  py::list Errors() const { return errors_; }

  /// A robot's Lua global (plain data: numbers, strings, booleans, tables as lists/dicts).
  py::object LuaGlobal(const py::object& robot, const std::string& name) const {
    const World& w = Live();
    const size_t i = RobotIndex(robot);
    const RobotDef& def = w.model.robots[i];
    if (def.controller >= 0 && w.model.controllers[def.controller].Cpp())
      throw Error("lua_global: robot '" + def.id + "' runs a C++ controller (<" +
                  w.model.controllers[def.controller].label + " id=\"" + def.controller_id +
                  "\">), which has no Lua globals");
    Value value;
    std::string error;
    if (!LuaGlobalToValue(LuaStateOf(w.controllers[i].get()), name, &value, &error))
      throw Error("lua_global: robot '" + w.model.robots[i].id + "', '" + name + "': " + error);
    return FromJsonText(ValueJsonText(value));
  }

  /// The arena now as a PNG, drawn as `essaim snapshot` draws a recorded tick: bytes, or
  /// written to `path` (then None).
  py::object Render(std::optional<std::string> path, int size) const {
#ifndef ESSAIM_HAVE_CAIRO
    throw Error("render: this essaim was built without Cairo (install libcairo2-dev and rebuild)");
#else
    if (size < 16 || size > 8192) throw Error("render: size must be 16..8192 px");
    std::string png = RenderNow(size);
    if (!path) return py::bytes(png);
    std::string error;
    if (!WriteFileAtomic(*path, png, &error)) throw Error("render: " + error);
    return py::none();
#endif
  }

  void Close() {
    world_.reset();
    model_.reset();
    out_lock_.Release();
  }

 private:
  size_t RobotIndex(const py::object& robot) const {
    const auto& robots = Robots();
    if (py::isinstance<py::int_>(robot)) {
      const long long i = robot.cast<long long>();
      if (i < 0 || static_cast<size_t>(i) >= robots.size())
        throw py::index_error("robot index " + std::to_string(i) + " out of range (" + std::to_string(robots.size()) +
                              " robots)");
      return static_cast<size_t>(i);
    }
    const std::string id = py::str(robot).cast<std::string>();
    for (size_t i = 0; i < robots.size(); ++i)
      if (robots[i].id == id) return i;
    throw py::key_error("no robot '" + id + "' (robot_ids lists them)");
  }

#ifdef ESSAIM_HAVE_CAIRO
  /// Through a one-frame recording: the snapshot renderer draws recordings only.
  std::string RenderNow(int size) const {
    py::object tempfile = py::module_::import("tempfile"), shutil = py::module_::import("shutil");
    const std::string dir = tempfile.attr("mkdtemp")(py::arg("prefix") = "essaim-render-").cast<std::string>();
    const std::string file = JoinPath(dir, kRecordingFile);
    std::string png, error;
    bool ok;
    {
      RecordingWriter writer;
      Recording rec;
      SnapshotOptions opt;
      opt.size = size;
      ok = writer.Open(file, Live(), 1, &error) && writer.Finish(Live(), &error) &&
           Recording::Read(file, &rec, &error) && RenderSnapshotPng(rec, rec.FrameCount() - 1, opt, &png, &error);
    }
    shutil.attr("rmtree")(dir, py::arg("ignore_errors") = true);
    if (!ok) throw Error("render: " + error);
    return png;
  }
#endif

  /// The robots as the run has them now: the loaded model's, then those the loop functions added.
  const std::vector<RobotDef>& Robots() const { return world_ ? world_->model.robots : model_->robots; }

  World& Live() const {
    if (!world_) throw Error("this Simulation is closed");
    return *world_;
  }
  std::string FailureText() const {
    std::string text = world_->failure;
    for (const ControllerError& e : world_->controller_errors) {
      if (!text.empty()) text += "\n";
      text += e.message;
    }
    return text.empty() ? "the run failed" : text;
  }

  std::string path_;
  LoadOptions load_;
  bool strict_ = false;
  std::string out_;
  std::unique_ptr<Model> model_;
  // The watchdog of this simulation's Lua states, declared before the World so it outlives
  // them. A call stuck inside a C function cannot be unwound: the process ends, as the CLI's.
  Watchdog watchdog_{[](const std::string& message) {
    std::fprintf(stderr, "essaim: %s\n", message.c_str());
    std::fflush(stderr);
    _exit(1);
  }};
  std::unique_ptr<World> world_;
  std::vector<LogLine> logs_;
  py::list errors_;
  size_t reported_errors_ = 0;
  OutFolderLock out_lock_;  // one run per folder, as the CLI's
  StepStatus status_ = StepStatus::Running;
  bool finished_ = false;
  py::object metrics_ = py::none(), summary_ = py::none();
  std::chrono::steady_clock::time_point t0_;
};

/// recording.bin read back (the replay's own parser): per-frame robot poses, alive flags and
/// battery as numpy arrays, or one long pandas table. A robot the loop functions added
/// during the run is absent from the frames before: `present` false, NaN pose and battery.
class RecordingData {
 public:
  explicit RecordingData(const std::string& path) {
    std::string error;
    Recording rec;
    const bool folder = py::module_::import("os.path").attr("isdir")(path).cast<bool>();
    if (!Recording::Read(folder ? JoinPath(path, kRecordingFile) : path, &rec, &error)) throw Simulation::Error(error);
    const auto frames = static_cast<py::ssize_t>(rec.FrameCount()), robots = static_cast<py::ssize_t>(rec.RobotCount());
    std::vector<uint64_t> ticks(static_cast<size_t>(frames));
    py::array_t<double> poses({frames, robots, py::ssize_t{3}}), battery({frames, robots});
    py::array_t<bool> alive({frames, robots}), present({frames, robots});
    auto p = poses.mutable_unchecked<3>();
    auto b = battery.mutable_unchecked<2>();
    auto a = alive.mutable_unchecked<2>();
    auto in = present.mutable_unchecked<2>();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (py::ssize_t f = 0; f < frames; ++f) {
      ticks[static_cast<size_t>(f)] = rec.Tick(static_cast<size_t>(f));
      for (py::ssize_t r = 0; r < robots; ++r) {
        const RecordedRobot robot = rec.Robot(static_cast<size_t>(f), static_cast<size_t>(r));
        const bool here = robot.present;
        p(f, r, 0) = here ? robot.x : nan, p(f, r, 1) = here ? robot.y : nan;
        p(f, r, 2) = here ? WrapYaw(robot.yaw) : nan;
        b(f, r) = here ? robot.battery : nan, a(f, r) = robot.alive, in(f, r) = here;
      }
    }
    ticks_ = py::module_::import("numpy").attr("array")(py::cast(ticks), "uint64");
    poses_ = poses, battery_ = battery, alive_ = alive, present_ = present;
    for (const std::string& id : rec.scene().robot_ids) robot_ids_.append(id);
    ticks_per_second_ = rec.scene().ticks_per_second;
    seed_ = rec.scene().seed;
  }

  /// One row per (recorded tick, robot present then): tick, robot, x, y, yaw, alive, battery.
  py::object ToPandas() const {
    py::module_ np = py::module_::import("numpy");
    const auto robots = static_cast<py::ssize_t>(py::len(robot_ids_));
    py::object poses = poses_.attr("reshape")(-1, 3);
    py::dict columns;
    columns["tick"] = np.attr("repeat")(ticks_, robots);
    columns["robot"] = np.attr("tile")(np.attr("array")(robot_ids_, py::arg("dtype") = "object"), py::len(ticks_));
    const char* names[] = {"x", "y", "yaw"};
    for (int k = 0; k < 3; ++k)
      columns[names[k]] = poses[py::make_tuple(py::slice(py::none(), py::none(), py::none()), k)];
    columns["alive"] = alive_.attr("reshape")(-1);
    columns["battery"] = battery_.attr("reshape")(-1);
    py::object table = py::module_::import("pandas").attr("DataFrame")(columns);
    if (present_.attr("all")().cast<bool>()) return table;  // the usual case: no robot added during the run
    return table[present_.attr("reshape")(-1)].attr("reset_index")(py::arg("drop") = true);
  }

  py::object ticks_, poses_, battery_, alive_, present_;
  py::list robot_ids_;
  uint32_t ticks_per_second_ = 0;
  uint64_t seed_ = 0;
};

}  // namespace
}  // namespace essaim

PYBIND11_MODULE(essaim, m) {
  using essaim::Simulation;
  m.doc() = "essaim: a headless swarm-robotics simulator (ARGoS foot-bots, Lua controllers)";
  m.attr("__version__") = ESSAIM_VERSION;
  py::register_exception<Simulation::Error>(m, "Error");
  py::class_<Simulation>(m, "Simulation")
      .def(py::init<const std::string&, std::optional<uint64_t>, std::optional<int>, std::optional<py::dict>,
                    std::optional<std::string>, bool>(),
           py::arg("path"), py::arg("seed") = py::none(), py::arg("threads") = py::none(),
           py::arg("overrides") = py::none(), py::arg("out") = py::none(), py::arg("strict") = false,
           "Loads an .argos experiment. overrides: {--set path: value}; out: folder for the CLI's output files; "
           "strict: unknown attributes in the file are errors, not warnings.")
      .def("step", &Simulation::StepN, py::arg("n") = 1,
           "Steps n ticks (fewer at the experiment's end); returns those stepped.")
      .def("run", &Simulation::Run, "Steps to the experiment's end; returns the ticks stepped.")
      .def_property_readonly("tick", &Simulation::Tick)
      .def_property_readonly("finished", &Simulation::Finished, "True once the experiment has ended (or failed).")
      .def_property_readonly("robot_ids", &Simulation::RobotIds)
      .def("poses", &Simulation::Poses, "robots x 3 float64 array: x, y (m), yaw (rad)")
      .def("alive", &Simulation::Alive, "bool array: robots with battery left")
      .def("battery", &Simulation::Battery, "float64 array: charge left / full charge")
      .def("led_colors", &Simulation::LedColors, "robots x 13 x 3 uint8 array (RGB)")
      .def("finish", &Simulation::Finish, "Ends the run; returns post_experiment's table (metrics.json) as a dict.")
      .def_property_readonly("summary", &Simulation::Summary,
                             "summary.json's content; before finish(), the run so far (status 'running')")
      .def_property_readonly(
          "errors", &Simulation::Errors,
          "controller errors so far: [{'robot', 'tick', 'message'}] (also logged to the 'essaim' logger)")
      .def("reset", &Simulation::Reset, py::arg("seed") = py::none(),
           "Starts again from tick 0 (files read again), with this seed or the same one.")
      .def(
          "lua_global", &Simulation::LuaGlobal, py::arg("robot"), py::arg("name"),
          "A robot's (id or index) Lua global as Python data: numbers, strings, booleans, lists, dicts; None if unset. "
          "An error for a robot running a C++ controller.")
      .def("render", &Simulation::Render, py::arg("path") = py::none(), py::arg("size") = 800,
           "The arena now as PNG (as `essaim snapshot`): bytes, or written to path.")
      .def("close", &Simulation::Close)
      .def(
          "__enter__", [](Simulation& s) -> Simulation& { return s; }, py::return_value_policy::reference)
      .def("__exit__", [](Simulation& s, py::object, py::object, py::object) { s.Close(); })
      .def("_repr_png_", [](const Simulation& s) { return s.Render(std::nullopt, 800); });
  using essaim::RecordingData;
  py::class_<RecordingData>(m, "Recording")
      .def_readonly("ticks", &RecordingData::ticks_, "uint64 (frames,): the tick of each frame")
      .def_readonly("robot_ids", &RecordingData::robot_ids_)
      .def_readonly("poses", &RecordingData::poses_, "float64 (frames, robots, 3): x, y (m), yaw in (-pi, pi]")
      .def_readonly("alive", &RecordingData::alive_, "bool (frames, robots)")
      .def_readonly("present", &RecordingData::present_,
                    "bool (frames, robots): false before the loop functions added that robot (NaN pose)")
      .def_readonly("battery", &RecordingData::battery_, "float64 (frames, robots): charge / full (1/255 steps)")
      .def_readonly("ticks_per_second", &RecordingData::ticks_per_second_)
      .def_readonly("seed", &RecordingData::seed_)
      .def("to_pandas", &RecordingData::ToPandas,
           "One row per (frame, robot present in it): tick, robot, x, y, yaw, alive, battery.");
  m.def(
      "read_recording", [](const std::string& path) { return RecordingData(path); }, py::arg("path"),
      "Reads a run's recording.bin (the file, or the run folder holding it).");
}
