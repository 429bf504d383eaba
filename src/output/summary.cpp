#include "output/summary.h"

#include <cmath>

#include "core/json.h"
#include "core/paths.h"
#include "core/strings.h"
#include "output/atomic_file.h"

namespace essaim {

namespace {
// The run's identity and the files it read (docs/cli.md: summary.json).
void AddInputs(Json& s, const std::string& version, const Model& m, const InputFiles& inputs) {
  s["run_identity"] = inputs.Identity(version, m.overrides, m.experiment.length_ticks, m.experiment.seed);
  s["inputs"] = Json::array();
  for (const InputFile& f : inputs.List())
    s["inputs"].push_back(Json::object({{"path", f.path}, {"role", f.role}, {"hash", f.hash}}));
}

Json BuildSummary(const World& w, const RunInfo& info) {
  const Model& m = w.model;
  Json s = Json::object();
  s["essaim_version"] = info.version;
  s["experiment"] = m.file;
  s["experiment_hash"] = "fnv1a64:" + m.file_hash;
  if (w.inputs) AddInputs(s, info.version, m, *w.inputs);
  s["overrides"] = Json::array();
  for (const std::string& o : m.overrides) s["overrides"].push_back(o);
  s["seed"] = static_cast<uint64_t>(m.experiment.seed);
  s["ticks"] = static_cast<uint64_t>(w.tick);
  s["ticks_per_second"] = m.experiment.ticks_per_second;
  s["robots"] = w.robots.size();
  int alive = 0;
  for (const RobotState& r : w.robots) alive += r.alive;
  s["robots_alive"] = alive;
  s["threads"] = w.threads;
  std::string status = info.status;
  if (!info.output_errors.empty() && (status == "ok" || status == "controller_error")) status = "failed";
  s["status"] = status;
  s["finished_by"] = info.finished_by;
  double steps = static_cast<double>(w.tick) * static_cast<double>(w.robots.size());
  s["wall_seconds"] = info.wall_seconds;
  s["robot_steps_per_second"] = info.wall_seconds > 0 ? steps / info.wall_seconds : 0.0;
  s["us_per_robot_step"] = steps > 0 ? info.wall_seconds * 1e6 / steps : 0.0;
  s["stage_seconds"] = Json::object({{"act", w.times.act},
                                     {"physics", w.times.physics},
                                     {"media", w.times.media},
                                     {"loop_functions", w.times.loop_functions},
                                     {"sense", w.times.sense},
                                     {"control", w.times.control}});
  const SetupTimes& setup = w.setup;
  s["setup_seconds"] = Json::object({{"load", setup.load},
                                     {"placement", setup.placement},
                                     {"world", setup.world},
                                     {"lua_states", setup.lua_states},
                                     {"init", setup.init},
                                     {"total", setup.Total()}});
  size_t peak = 0;
  for (const auto& c : w.controllers) peak += c->Memory().peak;
  s["lua_memory_bytes"] = peak;
  s["controller_errors"] = Json::array();
  for (const ControllerError& e : w.controller_errors)
    s["controller_errors"].push_back(
        Json::object({{"robot", e.robot}, {"tick", static_cast<uint64_t>(e.tick)}, {"message", e.message}}));
  std::string failure = w.failure;
  for (const std::string& e : info.output_errors) failure += (failure.empty() ? "" : "; ") + e;
  if (!info.failure.empty()) failure = info.failure;
  if (!failure.empty()) s["failure"] = failure;
  s["unread_params"] = Json::array();
  for (const UnreadParam& u : w.unread_params) {
    Json one = Json::object({{"path", u.path}});
    if (!u.did_you_mean.empty()) one["did_you_mean"] = u.did_you_mean;
    s["unread_params"].push_back(one);
  }
  s["outputs"] = info.outputs;
  return s;
}

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string CsvNumber(double v) {
  if (std::isnan(v)) return "NaN";
  if (std::isinf(v)) return v > 0 ? "Inf" : "-Inf";
  return FormatDouble(v);
}
}  // namespace

std::string SummaryJsonText(const World& world, const RunInfo& info) { return DumpJson(BuildSummary(world, info)); }

std::string TimeseriesCsv(const Timeseries& series) {
  std::string out;
  for (size_t i = 0; i < series.columns.size(); ++i) out += (i ? "," : "") + CsvField(series.columns[i]);
  out += "\n";
  for (const auto& row : series.rows) {
    for (size_t i = 0; i < row.size(); ++i) out += (i ? "," : "") + CsvNumber(row[i]);
    out += "\n";
  }
  return out;
}

bool WriteFailureSummary(const std::string& dir, const std::string& version, const std::string& experiment,
                         const std::vector<std::string>& overrides, const Model* model, const InputFiles* inputs,
                         const std::string& message, std::string* error) {
  Json s = Json::object();
  s["essaim_version"] = version;
  s["experiment"] = model ? model->file : experiment;
  if (model) s["experiment_hash"] = "fnv1a64:" + model->file_hash;
  if (model && inputs) AddInputs(s, version, *model, *inputs);
  s["overrides"] = overrides;
  if (model) {
    s["seed"] = static_cast<uint64_t>(model->experiment.seed);
    s["ticks_per_second"] = model->experiment.ticks_per_second;
    s["robots"] = model->robots.size();
  }
  s["ticks"] = 0;
  s["status"] = "failed";
  s["finished_by"] = "error";
  s["controller_errors"] = Json::array();
  s["failure"] = message;
  s["outputs"] = Json::array({"summary.json"});
  if (!MakeDirs(dir, error)) return false;
  return WriteFileAtomic(JoinPath(dir, "summary.json"), DumpJson(s), error);
}

bool WriteRunOutputs(const std::string& dir, const World& w, RunInfo info, const Value* metrics, std::string* error) {
  std::vector<std::string> failed;  // this function's own failures, for `error`
  auto write = [&](const char* name, const std::string& content) {
    std::string err;
    if (WriteFileAtomic(JoinPath(dir, name), content, &err))
      info.outputs.push_back(name);
    else
      failed.push_back(err);
  };
  if (!MakeDirs(dir, error)) return false;
  if (metrics) write("metrics.json", DumpJson(ToJson(*metrics)));
  const Timeseries& ts = w.loop_functions.Series();
  if (!ts.columns.empty()) write("timeseries.csv", TimeseriesCsv(ts));
  info.output_errors.insert(info.output_errors.end(), failed.begin(), failed.end());
  info.outputs.insert(info.outputs.begin(), "summary.json");
  std::string err;
  if (!WriteFileAtomic(JoinPath(dir, "summary.json"), SummaryJsonText(w, info), &err)) failed.push_back(err);
  error->clear();
  for (const std::string& e : failed) *error += (error->empty() ? "" : "; ") + e;
  return failed.empty();
}

}  // namespace essaim
