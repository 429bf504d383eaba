#include "debug/debug_session.h"

#include <lua.hpp>
#include <map>

#include "lua/debug/lua_inspect_frames.h"
#include "sim/world.h"

namespace essaim {

DebugSession::DebugSession(DapChannel& channel, Launcher launcher)
    : channel_(channel), launcher_(std::move(launcher)), debugger_(this) {}

bool DebugSession::Configure() {
  while (!configured_) {
    Value request;
    bool closed = false;
    if (!channel_.Read(&request, -1, &closed)) return false;
    if (StringField(request, "type") != "request") continue;
    Dispatch(request);
    if (terminate_ || detached_) return false;
  }
  return true;
}

DebugSession::After DebugSession::Dispatch(const Value& request) {
  using Run = std::function<After(DebugSession*, const Value&)>;
  struct Entry {
    bool stopped_only;  // answered only while the simulation is stopped
    Run run;
  };
  auto stay = [](void (DebugSession::*f)(const Value&)) -> Run {
    return [f](DebugSession* s, const Value& r) { return (s->*f)(r), After::Stay; };
  };
  auto step = [](StepMode mode) -> Run {
    return [mode](DebugSession* s, const Value& r) { return s->Resume(r, mode); };
  };
  static const std::map<std::string, Entry> table = {
      {"initialize", {false, stay(&DebugSession::Initialize)}},
      {"launch", {false, stay(&DebugSession::Launch)}},
      {"attach", {false, stay(&DebugSession::Launch)}},
      {"configurationDone", {false, stay(&DebugSession::ConfigurationDone)}},
      {"setBreakpoints", {false, stay(&DebugSession::SetBreakpoints)}},
      {"setFunctionBreakpoints", {false, stay(&DebugSession::SetFunctionBreakpoints)}},
      {"setExceptionBreakpoints", {false, stay(&DebugSession::SetExceptionBreakpoints)}},
      {"threads", {false, stay(&DebugSession::Threads)}},
      {"pause", {false, stay(&DebugSession::Pause)}},
      {"evaluate", {false, stay(&DebugSession::Evaluate)}},
      {"terminate", {false, [](DebugSession* s, const Value& r) { return s->Terminate(r); }}},
      {"disconnect", {false, [](DebugSession* s, const Value& r) { return s->Disconnect(r); }}},
      {"stackTrace", {true, stay(&DebugSession::StackTrace)}},
      {"scopes", {true, stay(&DebugSession::Scopes)}},
      {"variables", {true, stay(&DebugSession::Variables)}},
      {"setVariable", {true, stay(&DebugSession::SetVariable)}},
      {"continue", {true, step(StepMode::None)}},
      {"next", {true, step(StepMode::Over)}},
      {"stepIn", {true, step(StepMode::In)}},
      {"stepOut", {true, step(StepMode::Out)}},
      {"runToTick", {true, [](DebugSession* s, const Value& r) { return s->RunToTick(r); }}},
      {"stepBack", {true, stay(&DebugSession::GoBack)}},
      {"reverseContinue", {true, stay(&DebugSession::GoBack)}},
  };
  const std::string command = StringField(request, "command");
  auto found = table.find(command);
  if (found == table.end()) {
    channel_.Respond(request, Value(), false, "essaim debug does not handle '" + command + "'");
    return After::Stay;
  }
  if (found->second.stopped_only && !stop_.active) {
    channel_.Respond(request, Value(), false, command + ": the simulation is running (pause it first)");
    return After::Stay;
  }
  return found->second.run(this, request);
}

void DebugSession::ConfigurationDone(const Value& request) {
  configured_ = launched_;
  channel_.Respond(request, Value(), launched_, launched_ ? "" : "launch first");
}

void DebugSession::SendStopped(const std::string& reason, int thread, const std::string& description,
                               const std::string& text) {
  Value body = Value::MapOf({{"reason", Value::OfString(reason)},
                             {"threadId", Value::OfInteger(thread)},
                             {"allThreadsStopped", Value::OfBool(true)},
                             {"description", Value::OfString(description)}});
  if (!text.empty()) body.Set("text", Value::OfString(text));
  channel_.Event("stopped", std::move(body));
}

void DebugSession::ServeStopped() {
  last_thread_ = stop_.thread;
  const bool quiet = debugger_.Quiet();
  debugger_.SetQuiet(true);  // what the client evaluates never stops
  while (!detached_) {
    Value request;
    bool closed = false;
    if (!channel_.Read(&request, -1, &closed)) {
      // The client went away: the run goes on to its end without stopping.
      detached_ = true;
      debugger_.Detach();
      break;
    }
    if (StringField(request, "type") != "request") continue;
    if (Dispatch(request) == After::Resume) break;
  }
  debugger_.SetQuiet(quiet);
  Release();
  stop_ = Stop();
}

void DebugSession::Stopped(int thread, lua_State* L, const StopInfo& why) {
  if (detached_) return;
  if (replay_.active) FinishReplay();
  stop_ = {true, false, thread, L, why.first_level, why.reason};
  SendStopped(why.reason, thread, why.description, why.text);
  ServeStopped();
}

void DebugSession::BoundaryStop(const std::string& reason, int thread, const std::string& description) {
  if (replay_.active) FinishReplay();
  stop_ = {true, true, thread, nullptr, 0, reason};
  SendStopped(reason, thread, description, "");
  ServeStopped();
}

long long DebugSession::BoundaryTick() const { return world_ ? static_cast<long long>(world_->tick) + 1 : 1; }

bool DebugSession::BeforeTick(World& world) {
  world_ = &world;
  debugger_.SetTick(static_cast<long long>(world.tick));
  std::string order;
  if (checkpoints_ && divergences_.empty() && !detached_ && !terminate_ && checkpoints_->Due() &&
      checkpoints_->Take(static_cast<long long>(world.tick), &order))
    TakeOrder(order);  // this process is now the live simulation, going back
  if (replay_.active && !ReplayBoundary()) {
    debugger_.SetTick(BoundaryTick());
    return true;
  }
  ServePending();
  BoundaryStops(world);
  debugger_.SetTick(BoundaryTick());
  return !terminate_;
}

// Requests that came while running (pause, breakpoints), answered between ticks.
void DebugSession::ServePending() {
  while (!detached_ && !terminate_ && channel_.Pending()) {
    Value request;
    bool closed = false;
    if (!channel_.Read(&request, 0, &closed)) {
      if (closed) detached_ = true, debugger_.Detach();
      return;
    }
    if (StringField(request, "type") == "request") Dispatch(request);
  }
}

// The stops made at this boundary: entry, pause, run to tick.
void DebugSession::BoundaryStops(const World& world) {
  const std::string before = "before tick " + std::to_string(BoundaryTick());
  const int first = launch_.robot_ids.empty() ? 1 : 2;
  auto open = [this] { return !detached_ && !terminate_; };
  if (open() && world.tick == 0 && launch_.stop_on_entry) BoundaryStop("entry", first, before);
  if (open() && pause_thread_) {
    const int thread = pause_thread_;
    pause_thread_ = 0;
    BoundaryStop("pause", thread, before);
  }
  while (open() && run_to_tick_ > 0 && run_to_tick_ == BoundaryTick()) {
    run_to_tick_ = 0;
    BoundaryStop("goto", last_thread_ ? last_thread_ : first, before);
  }
}

void DebugSession::LogLine(char stream, const std::string& line) {
  if (detached_ || replay_.active) return;  // a going back's lines were sent the first time
  channel_.Output(stream == 'E' ? "stderr" : "stdout", line + "\n");
}

void DebugSession::Console(const std::string& text) {
  if (!detached_) channel_.Output("console", text);
}

Value DebugSession::Record() const {
  Value list = Value::EmptyList();
  list.list = divergences_;
  return Value::MapOf({{"divergences", std::move(list)}});
}

void DebugSession::Ended(int exit_code) {
  if (detached_ || channel_.Closed()) return;
  channel_.Event("exited", Value::MapOf({{"exitCode", Value::OfInteger(exit_code)}}));
  channel_.Event("terminated", Value::EmptyMap());
  // Editors answer `terminated` with a disconnect; answer it, then the process ends.
  for (int waited = 0; waited < 50; ++waited) {
    Value request;
    bool closed = false;
    if (!channel_.Read(&request, 100, &closed)) {
      if (closed) return;
      continue;
    }
    const std::string command = StringField(request, "command");
    if (command == "disconnect" || command == "terminate") {
      channel_.Respond(request, Value());
      return;
    }
    channel_.Respond(request, Value(), false, "the run has ended");
  }
}

void DebugSession::Release() {
  for (const Handle& h : handles_)
    if (h.ref >= 0)
      if (lua_State* L = StateFor(h.thread, -1)) ReleaseRef(L, h.ref);
  handles_.clear();
}

lua_State* DebugSession::StateFor(int thread, int level) const {
  if (level >= 0 && stop_.active && !stop_.boundary && stop_.thread == thread) return stop_.L;
  const LuaDebugger::Thread* t = debugger_.FindThread(thread);
  return t ? t->L : nullptr;
}

int DebugSession::NewHandle(Handle h) {
  handles_.push_back(h);
  return static_cast<int>(handles_.size());
}

std::string DebugSession::ThreadName(int thread) const {
  if (thread == 1) return "loop functions";
  const size_t i = static_cast<size_t>(thread - 2);
  return thread >= 2 && i < launch_.robot_ids.size() ? launch_.robot_ids[i] : "?";
}

}  // namespace essaim
