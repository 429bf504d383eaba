#include "serve/live_server.h"

#include <chrono>
#include <condition_variable>
#include <deque>
#include <future>
#include <mutex>
#include <optional>
#include <random>
#include <thread>
#include <vector>

#include "core/value_json.h"
#include "serve/control.h"
#include "serve/file_watcher.h"
#include "serve/live_experiment.h"
#include "serve/view_server.h"

namespace essaim {

namespace {
using Clock = std::chrono::steady_clock;
constexpr auto kFrameInterval = std::chrono::milliseconds(33);  // at most 30 frames per second
constexpr auto kWatchInterval = std::chrono::milliseconds(100);
constexpr size_t kLogKept = 2000;

struct LogLine {
  uint64_t number = 0, tick = 0;
  int robot = -1;
  char stream = 'O';
  std::string who;  // the robot's id, "loop_functions" or "essaim"
  std::string text;
};

struct Inspection {
  int robot = -1;
  std::promise<std::string> answer;
};

Value Numbers(const std::vector<double>& numbers) {
  Value v = Value::EmptyList();
  for (double x : numbers) v.list.push_back(Value::OfNumber(x));
  return v;
}

HttpResponse JsonAnswer(int status, const Value& body) { return {status, "application/json", ValueJsonLine(body)}; }
HttpResponse ErrorAnswer(int status, const std::string& message) {
  return JsonAnswer(status, Value::MapOf({{"error", Value::OfString(message)}}));
}
}  // namespace

struct LiveServer::Impl {
  ServeOptions options;
  std::unique_ptr<ViewServer> view;  // the page, /api/state, /api/scene, /api/events
  FileWatcher watcher;
  std::unique_ptr<LiveExperiment> experiment;

  // Shared with the HTTP threads, under `mutex`.
  std::mutex mutex;
  std::condition_variable wake;  // a command or an inspection arrived
  std::deque<ControlCommand> commands;
  std::vector<std::shared_ptr<Inspection>> inspections;
  std::deque<LogLine> log;
  uint64_t log_total = 0;
  std::vector<std::string> series_columns;
  std::vector<std::vector<double>> series_rows;
  uint64_t series_run = 0;

  // The simulation thread's own.
  bool playing = false;
  uint64_t ticks_left = 0;  // a step or run N in progress
  double speed = 1;         // multiple of real time; 0: max
  Clock::time_point pace_start;
  uint64_t pace_tick = 0;
  size_t series_copied = 0;
  // /api/scene's version and the entity layout it shows (sim thread only): boxes, cylinders
  // and lights the loop functions add or remove make a new scene at the next frame.
  uint64_t scene_version = 0, scene_layout = 0;
  Clock::time_point last_frame, last_watch;

  void AddLog(char stream, const std::string& text, const LogOrigin& from);
  void Routes();
  HttpResponse Control(const HttpRequest& req);
  HttpResponse Inspect(const HttpRequest& req);
  HttpResponse Log(const HttpRequest& req);
  HttpResponse Series(const HttpRequest& req);

  bool ApplyCommands();
  void Apply(const ControlCommand& c);
  void AnswerInspections();
  Value RobotLog(int robot);
  void Report(const std::string& line) const;
  void AfterLoad(bool ok, const char* what);
  bool WatchFiles();
  void StepOnce();
  void CopySeries();
  /// A new /api/scene when the loop functions added or removed entities since the last.
  void RefreshScene();
  void Pace();
  void Publish();
  void Loop(const std::atomic<int>& stop);
};

void LiveServer::Impl::AddLog(char stream, const std::string& text, const LogOrigin& from) {
  std::lock_guard<std::mutex> lock(mutex);
  const char* who = from.robot_id ? from.robot_id : from.robot == kLogLoopFunctions ? "loop_functions" : "essaim";
  log.push_back({++log_total, from.tick, from.robot, stream, who, text});
  if (log.size() > kLogKept) log.pop_front();
}

HttpResponse LiveServer::Impl::Control(const HttpRequest& req) {
  ControlCommand command;
  std::string error;
  if (!ParseControl(req.body, &command, &error)) return ErrorAnswer(400, error);
  {
    std::lock_guard<std::mutex> lock(mutex);
    commands.push_back(command);
  }
  wake.notify_all();
  return JsonAnswer(200, Value::MapOf({{"ok", Value::OfBool(true)}}));
}

HttpResponse LiveServer::Impl::Inspect(const HttpRequest& req) {
  auto inspection = std::make_shared<Inspection>();
  std::optional<long long> index = ParseIndex(req.Param("robot"));
  if (!index) return ErrorAnswer(400, "robot=N needs the robot's index (0, 1, ...)");
  inspection->robot = static_cast<int>(*index);
  std::future<std::string> answer = inspection->answer.get_future();
  {
    std::lock_guard<std::mutex> lock(mutex);
    inspections.push_back(inspection);
  }
  wake.notify_all();
  // A controller stuck in a long call keeps the simulation thread: answer "busy", not hang.
  if (answer.wait_for(std::chrono::seconds(3)) != std::future_status::ready)
    return ErrorAnswer(503, "the simulation is busy (a long step); try again");
  std::string body = answer.get();
  if (body == "null") return ErrorAnswer(404, "no robot " + std::to_string(*index));
  return {200, "application/json", body};
}

HttpResponse LiveServer::Impl::Log(const HttpRequest& req) {
  uint64_t from = static_cast<uint64_t>(ParseIndex(req.Param("from")).value_or(0));
  Value lines = Value::EmptyList();
  std::lock_guard<std::mutex> lock(mutex);
  for (const LogLine& l : log) {
    if (l.number <= from) continue;
    lines.list.push_back(Value::MapOf({{"n", Value::OfUnsigned(l.number)},
                                       {"tick", Value::OfUnsigned(l.tick)},
                                       {"robot", Value::OfInteger(l.robot)},
                                       {"who", Value::OfString(l.who)},
                                       {"error", Value::OfBool(l.stream == 'E')},
                                       {"text", Value::OfString(l.text)}}));
  }
  Value answer = Value::MapOf({{"total", Value::OfUnsigned(log_total)}});
  answer.Set("lines", std::move(lines));  // moved, not copied as a MapOf entry would be
  return JsonAnswer(200, answer);
}

HttpResponse LiveServer::Impl::Series(const HttpRequest& req) {
  size_t from = static_cast<size_t>(ParseIndex(req.Param("from")).value_or(0));
  std::lock_guard<std::mutex> lock(mutex);
  Value rows = Value::EmptyList();
  for (size_t i = from; i < series_rows.size(); ++i) rows.list.push_back(Numbers(series_rows[i]));
  Value answer = Value::MapOf({{"run", Value::OfUnsigned(series_run)},
                               {"columns", Value::OfStrings(series_columns)},
                               {"from", Value::OfUnsigned(from)}});
  answer.Set("rows", std::move(rows));
  return JsonAnswer(200, answer);
}

void LiveServer::Impl::Routes() {
  HttpServer& http = view->Http();
  http.Get("/api/robot", [this](const HttpRequest& req) { return Inspect(req); });
  http.Get("/api/log", [this](const HttpRequest& req) { return Log(req); });
  http.Get("/api/series", [this](const HttpRequest& req) { return Series(req); });
  http.Post("/api/control", [this](const HttpRequest& req) { return Control(req); });
}

// ---- the simulation thread ---------------------------------------------------------------

bool LiveServer::Impl::ApplyCommands() {
  std::deque<ControlCommand> todo;
  {
    std::lock_guard<std::mutex> lock(mutex);
    todo.swap(commands);
  }
  for (const ControlCommand& c : todo) Apply(c);
  return !todo.empty();
}

void LiveServer::Impl::Apply(const ControlCommand& c) {
  switch (c.kind) {
    case ControlKind::Play:
      playing = true;
      ticks_left = 0;
      break;
    case ControlKind::Pause:
      playing = false;
      ticks_left = 0;
      break;
    case ControlKind::Step:
      playing = false;
      ticks_left = c.ticks;
      break;
    case ControlKind::Speed:
      speed = c.speed;
      break;
    case ControlKind::Reset: {
      std::optional<uint64_t> seed = c.seed;
      if (c.new_seed) seed = std::random_device()() % 1000000;
      playing = false;
      ticks_left = 0;
      AfterLoad(experiment->Reset(seed), "reset");
      if (seed) AddLog('O', "reset with seed " + std::to_string(*seed), {0, kLogHost});
      break;
    }
  }
  pace_start = Clock::now();
  pace_tick = experiment->world() ? experiment->world()->tick : 0;
}

void LiveServer::Impl::AnswerInspections() {
  std::vector<std::shared_ptr<Inspection>> todo;
  {
    std::lock_guard<std::mutex> lock(mutex);
    todo.swap(inspections);
  }
  for (auto& in : todo) {
    Value j = experiment->Inspect(in->robot);
    if (!j.IsNull()) j.Set("log", RobotLog(in->robot));
    in->answer.set_value(ValueJsonLine(j));
  }
}

/// The robot's last 50 log lines, oldest first.
Value LiveServer::Impl::RobotLog(int robot) {
  Value lines = Value::EmptyList();
  std::lock_guard<std::mutex> lock(mutex);
  for (const LogLine& l : log)
    if (l.robot == robot)
      lines.list.push_back(Value::MapOf({{"tick", Value::OfUnsigned(l.tick)},
                                         {"error", Value::OfBool(l.stream == 'E')},
                                         {"text", Value::OfString(l.text)}}));
  if (lines.list.size() > 50) lines.list.erase(lines.list.begin(), lines.list.end() - 50);
  return lines;
}

/// After a load, reload or reset: the new scene and an empty series (ok), or the error,
/// the last good experiment staying (not ok). Reported too.
void LiveServer::Impl::AfterLoad(bool ok, const char* what) {
  if (!ok) {
    Report(std::string(what) + " failed, the last good experiment stays loaded:\n" + experiment->Error());
    return;
  }
  std::string scene_json = experiment->world() ? SceneText(*experiment->world()) : "null";
  if (experiment->world()) scene_layout = experiment->world()->entities.LayoutVersion();
  ++scene_version;
  view->SetScene(std::move(scene_json));
  {
    std::lock_guard<std::mutex> lock(mutex);
    series_columns.clear();
    series_rows.clear();
    series_run = experiment->run();
  }
  series_copied = 0;
  CopySeries();
  if (!experiment->Error().empty())
    Report(experiment->Error());
  else if (experiment->run() > 1)
    Report(std::string(what) + ", run " + std::to_string(experiment->run()));
}

void LiveServer::Impl::Report(const std::string& line) const {
  if (options.report) options.report(line);
}

/// On a change to a watched file: reload, reset, pause.
bool LiveServer::Impl::WatchFiles() {
  last_watch = Clock::now();
  std::vector<std::string> changed;
  if (!watcher.WaitForChange(0, &changed)) return false;
  Report(changed.front() + " changed, reloading");
  playing = false;
  ticks_left = 0;
  AfterLoad(experiment->Load(), "reload");
  watcher.Watch(experiment->InputFiles());  // a new require, a new floor image...
  return true;
}

void LiveServer::Impl::CopySeries() {
  const World* w = experiment->world();
  if (!w) return;
  const Timeseries& ts = w->loop_functions.Series();
  if (ts.rows.size() == series_copied) return;
  std::lock_guard<std::mutex> lock(mutex);
  if (series_columns.size() != ts.columns.size()) series_columns = ts.columns;
  for (size_t i = series_copied; i < ts.rows.size(); ++i) series_rows.push_back(ts.rows[i]);
  series_copied = ts.rows.size();
}

void LiveServer::Impl::StepOnce() {
  StepStatus status = experiment->Step();
  if (ticks_left > 0 && --ticks_left == 0) last_frame = {};  // the last tick of a step is shown
  if (status != StepStatus::Running) {
    playing = false;
    ticks_left = 0;
    last_frame = {};
  }
  CopySeries();
}

/// Below max speed, waits until the tick is due (a command cuts the wait short).
void LiveServer::Impl::Pace() {
  const World* w = experiment->world();
  if (speed <= 0 || !w) return;
  double rate = speed * w->model.experiment.ticks_per_second;
  auto due = pace_start +
             std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>((w->tick - pace_tick) / rate));
  auto now = Clock::now();
  if (due < now - std::chrono::milliseconds(250)) {  // far behind: do not try to catch up
    pace_start = now;
    pace_tick = w->tick;
    return;
  }
  std::unique_lock<std::mutex> lock(mutex);
  wake.wait_until(lock, due, [this] { return !commands.empty() || !inspections.empty(); });
}

void LiveServer::Impl::RefreshScene() {
  const World* w = experiment->world();
  if (!w || w->entities.LayoutVersion() == scene_layout) return;
  std::string text = SceneText(*w);  // once per frame at most: the floor is encoded anew
  scene_layout = w->entities.LayoutVersion();
  ++scene_version;
  view->SetScene(std::move(text));
}

void LiveServer::Impl::Publish() {
  last_frame = Clock::now();
  RefreshScene();
  FrameInfo info;
  info.scene = scene_version;
  info.run = experiment->run();
  info.paused = !playing && ticks_left == 0;
  info.speed = speed;
  info.error = experiment->Error();
  {
    std::lock_guard<std::mutex> lock(mutex);
    info.series_rows = series_rows.size();
    info.log_lines = log_total;
  }
  const World* w = experiment->world();
  view->Frames().Publish(w ? FrameText(*w, info)
                           : ValueJsonLine(Value::MapOf({{"tick", Value::OfUnsigned(0)},
                                                         {"run", Value::OfUnsigned(info.run)},
                                                         {"paused", Value::OfBool(true)},
                                                         {"speed", Value::OfNumber(speed)},
                                                         {"error", Value::OfString(info.error)},
                                                         {"robots", Value::EmptyList()}})));
}

void LiveServer::Impl::Loop(const std::atomic<int>& stop) {
  Publish();
  while (!stop) {
    bool changed = ApplyCommands();
    AnswerInspections();
    if (Clock::now() - last_watch >= kWatchInterval) changed |= WatchFiles();
    bool running = (playing || ticks_left > 0) && experiment->world();
    if (running) {
      StepOnce();
      Pace();
    } else {
      std::unique_lock<std::mutex> lock(mutex);
      wake.wait_for(lock, kWatchInterval, [this] { return !commands.empty() || !inspections.empty(); });
    }
    if (changed || (running && Clock::now() - last_frame >= kFrameInterval)) Publish();
  }
}

LiveServer::LiveServer(ServeOptions options) : impl_(std::make_unique<Impl>()) {
  impl_->options = std::move(options);
  impl_->view = std::make_unique<ViewServer>(impl_->options.page);
}

LiveServer::~LiveServer() { impl_->view->Stop(); }

bool LiveServer::Start(std::string* error) {
  Impl& s = *impl_;
  if (!s.watcher.Ok()) {
    *error = s.watcher.Error();
    return false;
  }
  s.experiment = std::make_unique<LiveExperiment>(
      s.options.file, s.options.load,
      [&s](char stream, const std::string& line, const LogOrigin& from) { s.AddLog(stream, line, from); },
      s.options.watchdog);
  s.AfterLoad(s.experiment->Load(), "load");
  s.watcher.Watch(s.experiment->InputFiles());
  s.Routes();
  return s.view->Start(s.options.host, s.options.port, s.options.token, error);
}

std::string LiveServer::Url() const { return impl_->view->Url(impl_->options.host); }

void LiveServer::Run(const std::atomic<int>& stop) {
  impl_->Loop(stop);
  impl_->view->Stop();
}

}  // namespace essaim
