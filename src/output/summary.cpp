#include "output/summary.h"

#include <cmath>

#include "core/paths.h"
#include "core/strings.h"
#include "core/value_json.h"
#include "output/atomic_file.h"

namespace essaim {

namespace {
Value Text(std::string s) { return Value::OfString(std::move(s)); }

// The run's identity and the files it read (docs/cli.md: summary.json).
void AddInputs(Value& s, const std::string& version, const Model& m, const InputFiles& inputs) {
  s.Set("run_identity", Text(inputs.Identity(version, m.overrides, m.experiment.length_ticks, m.experiment.seed)));
  Value list = Value::EmptyList();
  for (const InputFile& f : inputs.List())
    list.list.push_back(Value::MapOf({{"path", Text(f.path)}, {"role", Text(f.role)}, {"hash", Text(f.hash)}}));
  s.Set("inputs", std::move(list));
}

Value StageSeconds(const StageTimes& t) {
  return Value::MapOf({{"act", Value::OfNumber(t.act)},
                       {"physics", Value::OfNumber(t.physics)},
                       {"media", Value::OfNumber(t.media)},
                       {"loop_functions", Value::OfNumber(t.loop_functions)},
                       {"sense", Value::OfNumber(t.sense)},
                       {"control", Value::OfNumber(t.control)}});
}

Value SetupSeconds(const SetupTimes& t) {
  return Value::MapOf({{"load", Value::OfNumber(t.load)},
                       {"placement", Value::OfNumber(t.placement)},
                       {"world", Value::OfNumber(t.world)},
                       {"lua_states", Value::OfNumber(t.lua_states)},
                       {"init", Value::OfNumber(t.init)},
                       {"total", Value::OfNumber(t.Total())}});
}

Value ControllerErrors(const std::vector<ControllerError>& errors) {
  Value list = Value::EmptyList();
  for (const ControllerError& e : errors)
    list.list.push_back(
        Value::MapOf({{"robot", Text(e.robot)}, {"tick", Value::OfUnsigned(e.tick)}, {"message", Text(e.message)}}));
  return list;
}

Value UnreadParams(const std::vector<UnreadParam>& unread) {
  Value list = Value::EmptyList();
  for (const UnreadParam& u : unread) {
    Value one = Value::MapOf({{"path", Text(u.path)}});
    if (!u.did_you_mean.empty()) one.Set("did_you_mean", Text(u.did_you_mean));
    list.list.push_back(std::move(one));
  }
  return list;
}

// How long the run took: in all, per robot-step, per stage.
void AddTimes(Value& s, const World& w, const RunInfo& info) {
  const double steps = static_cast<double>(w.robot_steps);
  s.Set("wall_seconds", Value::OfNumber(info.wall_seconds));
  s.Set("robot_steps_per_second", Value::OfNumber(info.wall_seconds > 0 ? steps / info.wall_seconds : 0.0));
  s.Set("us_per_robot_step", Value::OfNumber(steps > 0 ? info.wall_seconds * 1e6 / steps : 0.0));
  s.Set("stage_seconds", StageSeconds(w.times));
  s.Set("setup_seconds", SetupSeconds(w.setup));
}

std::string Failure(const World& w, const RunInfo& info) {
  if (!info.failure.empty()) return info.failure;
  std::string failure = w.failure;
  for (const std::string& e : info.output_errors) failure += (failure.empty() ? "" : "; ") + e;
  return failure;
}

Value BuildSummary(const World& w, const RunInfo& info) {
  const Model& m = w.model;
  Value s = Value::EmptyMap();
  s.Set("essaim_version", Text(info.version));
  s.Set("experiment", Text(m.file));
  s.Set("experiment_hash", Text("fnv1a64:" + m.file_hash));
  if (w.inputs) AddInputs(s, info.version, m, *w.inputs);
  s.Set("overrides", Value::OfStrings(m.overrides));
  s.Set("seed", Value::OfUnsigned(m.experiment.seed));
  s.Set("ticks", Value::OfUnsigned(w.tick));
  s.Set("ticks_per_second", Value::OfInteger(m.experiment.ticks_per_second));
  s.Set("robots", Value::OfUnsigned(w.robots.size()));
  int alive = 0;
  for (const RobotState& r : w.robots) alive += r.alive;
  s.Set("robots_alive", Value::OfInteger(alive));
  s.Set("threads", Value::OfInteger(w.threads));
  std::string status = info.status;
  if (!info.output_errors.empty() && (status == "ok" || status == "controller_error")) status = "failed";
  s.Set("status", Text(status));
  s.Set("finished_by", Text(info.finished_by));
  AddTimes(s, w, info);
  size_t peak = 0;
  for (const auto& c : w.controllers) peak += c->Memory().peak;
  s.Set("lua_memory_bytes", Value::OfUnsigned(peak));
  s.Set("controller_errors", ControllerErrors(w.controller_errors));
  std::string failure = Failure(w, info);
  if (!failure.empty()) s.Set("failure", Text(failure));
  s.Set("unread_params", UnreadParams(w.unread_params));
  s.Set("outputs", Value::OfStrings(info.outputs));
  if (info.files_listed) s.Set("files", Value::OfStrings(info.files));
  if (info.crashed) {
    const RunInfo::Crash& c = info.crash;
    s.Set("crash", Value::MapOf({{"robot", Text(c.robot)},
                                 {"call", Text(c.call)},
                                 {"signal", Text(c.signal)},
                                 {"tick", Value::OfUnsigned(c.tick)}}));
  }
  if (!info.debug.IsNull()) s.Set("debug", info.debug);
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

std::string SummaryJsonText(const World& world, const RunInfo& info) {
  return ValueJsonText(BuildSummary(world, info));
}

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
  Value s = Value::EmptyMap();
  s.Set("essaim_version", Text(version));
  s.Set("experiment", Text(model ? model->file : experiment));
  if (model) s.Set("experiment_hash", Text("fnv1a64:" + model->file_hash));
  if (model && inputs) AddInputs(s, version, *model, *inputs);
  s.Set("overrides", Value::OfStrings(overrides));
  if (model) {
    s.Set("seed", Value::OfUnsigned(model->experiment.seed));
    s.Set("ticks_per_second", Value::OfInteger(model->experiment.ticks_per_second));
    s.Set("robots", Value::OfUnsigned(model->robots.size()));
  }
  s.Set("ticks", Value::OfInteger(0));
  s.Set("status", Text("failed"));
  s.Set("finished_by", Text("error"));
  s.Set("controller_errors", Value::EmptyList());
  s.Set("failure", Text(message));
  s.Set("outputs", Value::OfStrings({"summary.json"}));
  if (!MakeDirs(dir, error)) return false;
  return WriteFileAtomic(JoinPath(dir, "summary.json"), ValueJsonText(s), error);
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
  if (metrics) write("metrics.json", ValueJsonText(*metrics));
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
