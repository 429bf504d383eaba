#include "output/summary.h"

#include "core/strings.h"
#include "output/atomic_file.h"

namespace essaim {

Json BuildSummary(const World& w, const RunInfo& info) {
  const Model& m = w.model;
  Json s = Json::Object();
  s.Set("essaim_version", Json::String(info.version));
  s.Set("experiment", Json::String(m.file));
  s.Set("experiment_hash", Json::String("fnv1a64:" + m.file_hash));
  Json ov = Json::Array();
  for (const std::string& o : m.overrides) ov.Push(Json::String(o));
  s.Set("overrides", ov);
  s.Set("seed", Json::Int(static_cast<int64_t>(m.experiment.seed)));
  s.Set("ticks", Json::Int(static_cast<int64_t>(w.tick)));
  s.Set("ticks_per_second", Json::Int(m.experiment.ticks_per_second));
  s.Set("robots", Json::Int(static_cast<int64_t>(w.robots.size())));
  int alive = 0;
  for (const RobotState& r : w.robots) alive += r.alive;
  s.Set("robots_alive", Json::Int(alive));
  s.Set("threads", Json::Int(w.threads));
  s.Set("status", Json::String(info.status));
  s.Set("finished_by", Json::String(info.finished_by));
  double steps = static_cast<double>(w.tick) * static_cast<double>(w.robots.size());
  s.Set("wall_seconds", Json::Number(info.wall_seconds));
  s.Set("robot_steps_per_second", Json::Number(info.wall_seconds > 0 ? steps / info.wall_seconds : 0));
  s.Set("us_per_robot_step", Json::Number(steps > 0 ? info.wall_seconds * 1e6 / steps : 0));
  Json st = Json::Object();
  st.Set("act", Json::Number(w.times.act));
  st.Set("physics", Json::Number(w.times.physics));
  st.Set("media", Json::Number(w.times.media));
  st.Set("loop_functions", Json::Number(w.times.loop_functions));
  st.Set("sense", Json::Number(w.times.sense));
  st.Set("control", Json::Number(w.times.control));
  s.Set("stage_seconds", st);
  size_t peak = 0;
  for (const auto& c : w.controllers) peak += c->Memory().peak;
  s.Set("lua_memory_bytes", Json::Int(static_cast<int64_t>(peak)));
  Json errs = Json::Array();
  for (const ControllerError& e : w.controller_errors) {
    Json x = Json::Object();
    x.Set("robot", Json::String(e.robot));
    x.Set("tick", Json::Int(static_cast<int64_t>(e.tick)));
    x.Set("message", Json::String(e.message));
    errs.Push(x);
  }
  s.Set("controller_errors", errs);
  if (!w.failure.empty()) s.Set("failure", Json::String(w.failure));
  Json outs = Json::Array();
  for (const std::string& o : info.outputs) outs.Push(Json::String(o));
  s.Set("outputs", outs);
  return s;
}

std::string TimeseriesCsv(const Timeseries& series) {
  std::string out;
  for (size_t i = 0; i < series.columns.size(); ++i) out += (i ? "," : "") + series.columns[i];
  out += "\n";
  for (const auto& row : series.rows) {
    for (size_t i = 0; i < row.size(); ++i) out += (i ? "," : "") + FormatDouble(row[i]);
    out += "\n";
  }
  return out;
}

bool WriteRunOutputs(const std::string& dir, const World& w, RunInfo info, const Json* metrics, std::string* error) {
  if (!MakeDirs(dir, error)) return false;
  if (metrics) {
    if (!WriteFileAtomic(JoinPath(dir, "metrics.json"), metrics->Dump(), error)) return false;
    info.outputs.push_back("metrics.json");
  }
  const Timeseries& ts = w.loop_functions.Series();
  if (!ts.columns.empty()) {
    if (!WriteFileAtomic(JoinPath(dir, "timeseries.csv"), TimeseriesCsv(ts), error)) return false;
    info.outputs.push_back("timeseries.csv");
  }
  info.outputs.insert(info.outputs.begin(), "summary.json");
  return WriteFileAtomic(JoinPath(dir, "summary.json"), BuildSummary(w, info).Dump(), error);
}

}  // namespace essaim
