#include "debug/debug_session.h"

#include <lua.hpp>

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
  const std::string command = StringField(request, "command");
  if (command == "initialize") return Initialize(request), After::Stay;
  if (command == "launch" || command == "attach") return Launch(request), After::Stay;
  if (command == "configurationDone") {
    configured_ = launched_;
    channel_.Respond(request, Value(), launched_, launched_ ? "" : "launch first");
    return After::Stay;
  }
  if (command == "setBreakpoints") return SetBreakpoints(request), After::Stay;
  if (command == "setFunctionBreakpoints") return SetFunctionBreakpoints(request), After::Stay;
  if (command == "setExceptionBreakpoints") return SetExceptionBreakpoints(request), After::Stay;
  if (command == "threads") return Threads(request), After::Stay;
  if (command == "pause") return Pause(request), After::Stay;
  if (command == "terminate") return Terminate(request);
  if (command == "disconnect") return Disconnect(request);
  const bool stopped_only = command == "stackTrace" || command == "scopes" || command == "variables" ||
                            command == "setVariable" || command == "continue" || command == "next" ||
                            command == "stepIn" || command == "stepOut" || command == "runToTick" ||
                            command == "stepBack" || command == "reverseContinue";
  if (stopped_only && !stop_.active) {
    channel_.Respond(request, Value(), false, command + ": the simulation is running (pause it first)");
    return After::Stay;
  }
  if (command == "stackTrace") return StackTrace(request), After::Stay;
  if (command == "scopes") return Scopes(request), After::Stay;
  if (command == "variables") return Variables(request), After::Stay;
  if (command == "evaluate") return Evaluate(request), After::Stay;
  if (command == "setVariable") return SetVariable(request), After::Stay;
  if (command == "continue") return Resume(request, StepMode::None);
  if (command == "next") return Resume(request, StepMode::Over);
  if (command == "stepIn") return Resume(request, StepMode::In);
  if (command == "stepOut") return Resume(request, StepMode::Out);
  if (command == "runToTick") return RunToTick(request);
  if (command == "stepBack" || command == "reverseContinue") return GoBack(request), After::Stay;
  channel_.Respond(request, Value(), false, "essaim debug does not handle '" + command + "'");
  return After::Stay;
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
  while (!detached_ && !terminate_ && channel_.Pending()) {
    Value request;
    bool closed = false;
    if (!channel_.Read(&request, 0, &closed)) {
      if (closed) detached_ = true, debugger_.Detach();
      break;
    }
    if (StringField(request, "type") == "request") Dispatch(request);
  }
  const std::string before = "before tick " + std::to_string(BoundaryTick());
  const int first = launch_.robot_ids.empty() ? 1 : 2;
  if (!detached_ && !terminate_ && world.tick == 0 && launch_.stop_on_entry) BoundaryStop("entry", first, before);
  if (!detached_ && !terminate_ && pause_thread_) {
    const int thread = pause_thread_;
    pause_thread_ = 0;
    BoundaryStop("pause", thread, before);
  }
  while (!detached_ && !terminate_ && run_to_tick_ > 0 && run_to_tick_ == BoundaryTick()) {
    run_to_tick_ = 0;
    BoundaryStop("goto", last_thread_ ? last_thread_ : first, before);
  }
  debugger_.SetTick(BoundaryTick());
  return !terminate_;
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
