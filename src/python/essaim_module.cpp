// The `essaim` Python module (pybind11; the only file that includes it). A Simulation owns
// its Model and World: no global state, so several run in threads at once; the GIL is
// released while stepping. Runs use the CLI's loader, step and output code (bit-identical
// results, same files in `out`).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <string>

#include "output/atomic_file.h"
#include "core/paths.h"
#include "output/out_folder.h"
#include "model/xml_loader.h"
#include "output/run_end.h"
#include "output/summary.h"
#include "sim/step.h"

namespace py = pybind11;

namespace essaim {
namespace {

// Ticks stepped between two checks for Ctrl-C (needs the GIL back briefly).
constexpr uint64_t kSignalCheckTicks = 256;

py::object FromJson(const Json& j) {
  // Through Python's json module: the Json class stays an implementation detail.
  return py::module_::import("json").attr("loads")(DumpJson(j));
}

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
             std::optional<py::dict> overrides, std::optional<std::string> out, bool strict) {
    CheckArguments(path, threads, out);
    LoadOptions load;
    load.strict = strict;
    load.seed = seed;
    load.threads = threads;
    if (overrides)
      for (auto item : *overrides) load.overrides.push_back(py::str(item.first).cast<std::string>() + "=" + ValueText(item.second));
    ErrorList errors, warnings;
    model_ = LoadExperimentFile(path, load, &errors, &warnings);
    if (!model_) throw Error(errors.Format());
    // The CLI's warnings (unknown attributes...) as Python warnings, one per line.
    for (const InputError& w : warnings.Items()) {
      ErrorList one;
      one.Add(w.file, w.line, w.element, w.message);
      std::string text = one.Format();
      while (!text.empty() && text.back() == '\n') text.pop_back();
      py::module_::import("warnings").attr("warn")(text, py::module_::import("builtins").attr("UserWarning"), 2);
    }
    out_ = out.value_or("");
    std::string error;
    if (!out_.empty() && (!PrepareOutFolder(out_, &error) || !out_lock_.Acquire(out_, &error))) throw Error(error);
    SimOptions opt;
    opt.output_dir = out_;
    opt.lua.memory_limit = 64u << 20;  // the CLI's limits
    opt.lua.instruction_limit = 100000000;
    t0_ = std::chrono::steady_clock::now();
    {
      py::gil_scoped_release nogil;
      world_ = World::Create(*model_, opt, &error);
    }
    if (!world_) throw Error(error);
    if (!world_->failure.empty()) throw Error(world_->failure);  // an init() error
    // As `essaim run`: the folder holds this run's outputs only; an earlier run's are moved.
    std::vector<std::string> moved;
    if (!out_.empty() && !SetAsideEarlierOutputs(out_, &moved, &error)) throw Error(error);
    if (!moved.empty()) {
      std::string names;
      for (const std::string& name : moved) names += (names.empty() ? "" : ", ") + name;
      py::module_::import("warnings").attr("warn")(out_ + " held an earlier run's outputs; moved them into " +
                                                   JoinPath(out_, kPreviousRunFolder) + ": " + names);
    }
    if (LengthReached(*world_)) status_ = StepStatus::Finished;
  }

  struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
  };

  /// Steps up to n ticks (fewer when the experiment ends); returns the ticks stepped.
  uint64_t StepN(uint64_t n) {
    World& w = Live();
    if (finished_) throw Error("step: this run has ended (finish() was called)");
    uint64_t done = 0;
    while (done < n && status_ == StepStatus::Running) {
      uint64_t chunk = std::min<uint64_t>(n - done, kSignalCheckTicks);
      {
        py::gil_scoped_release nogil;
        for (uint64_t i = 0; i < chunk && status_ == StepStatus::Running; ++i, ++done) status_ = Step(w);
      }
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
    for (const RobotDef& r : model_->robots) ids.append(r.id);
    return ids;
  }

  py::array_t<double> Poses() const {
    const World& w = Live();
    py::array_t<double> a({static_cast<py::ssize_t>(w.robots.size()), py::ssize_t{3}});
    auto m = a.mutable_unchecked<2>();
    for (size_t i = 0; i < w.robots.size(); ++i) {
      Pose2 p = w.physics.RobotPose(static_cast<int>(i));
      m(i, 0) = p.x, m(i, 1) = p.y, m(i, 2) = p.yaw;
    }
    return a;
  }

  py::array_t<bool> Alive() const {
    const World& w = Live();
    py::array_t<bool> a(static_cast<py::ssize_t>(w.robots.size()));
    auto m = a.mutable_unchecked<1>();
    for (size_t i = 0; i < w.robots.size(); ++i) m(i) = w.robots[i].alive;
    return a;
  }

  /// Charge left as a fraction of the full charge (the battery sensor's available_charge).
  py::array_t<double> Battery() const {
    const World& w = Live();
    py::array_t<double> a(static_cast<py::ssize_t>(w.robots.size()));
    auto m = a.mutable_unchecked<1>();
    for (size_t i = 0; i < w.robots.size(); ++i) {
      double full = model_->robots[i].battery.full_charge;
      m(i) = full > 0 ? w.robots[i].battery.charge / full : 0.0;
    }
    return a;
  }

  py::array_t<uint8_t> LedColors() const {
    const World& w = Live();
    py::array_t<uint8_t> a({static_cast<py::ssize_t>(w.robots.size()), py::ssize_t{footbot::kLedCount}, py::ssize_t{3}});
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
    Json metrics;
    bool has_metrics = false;
    {
      py::gil_scoped_release nogil;
      EndRun(w, status_, &info, &metrics, &has_metrics);
    }
    bool ok = !(info.status == "failed" && status_ != StepStatus::Failed);
    std::string error;
    info.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    finished_ = true;
    summary_ = FromJson(BuildSummary(w, info));
    metrics_ = has_metrics ? FromJson(metrics) : py::dict();
    if (!out_.empty() && !WriteRunOutputs(out_, w, info, has_metrics ? &metrics : nullptr, &error)) throw Error(error);
    if (!ok) throw Error(w.failure);
    return metrics_;
  }

  py::object Summary() const {
    if (!finished_) throw Error("summary: call finish() first");
    return summary_;
  }

  void Close() {
    world_.reset();
    model_.reset();
    out_lock_.Release();
  }

 private:
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

  std::unique_ptr<Model> model_;
  std::unique_ptr<World> world_;
  std::string out_;
  OutFolderLock out_lock_;  // one run per folder, as the CLI's
  StepStatus status_ = StepStatus::Running;
  bool finished_ = false;
  py::object metrics_ = py::none(), summary_ = py::none();
  std::chrono::steady_clock::time_point t0_;
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
      .def("step", &Simulation::StepN, py::arg("n") = 1, "Steps n ticks (fewer at the experiment's end); returns those stepped.")
      .def("run", &Simulation::Run, "Steps to the experiment's end; returns the ticks stepped.")
      .def_property_readonly("tick", &Simulation::Tick)
      .def_property_readonly("finished", &Simulation::Finished, "True once the experiment has ended (or failed).")
      .def_property_readonly("robot_ids", &Simulation::RobotIds)
      .def("poses", &Simulation::Poses, "robots x 3 float64 array: x, y (m), yaw (rad)")
      .def("alive", &Simulation::Alive, "bool array: robots with battery left")
      .def("battery", &Simulation::Battery, "float64 array: charge left / full charge")
      .def("led_colors", &Simulation::LedColors, "robots x 13 x 3 uint8 array (RGB)")
      .def("finish", &Simulation::Finish, "Ends the run; returns post_experiment's table (metrics.json) as a dict.")
      .def_property_readonly("summary", &Simulation::Summary, "summary.json's content, after finish()")
      .def("close", &Simulation::Close)
      .def("__enter__", [](Simulation& s) -> Simulation& { return s; }, py::return_value_policy::reference)
      .def("__exit__", [](Simulation& s, py::object, py::object, py::object) { s.Close(); });
}
