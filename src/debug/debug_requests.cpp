// The DAP requests DebugSession answers, one function each.
#include <algorithm>
#include <filesystem>
#include <lua.hpp>

#include "debug/debug_session.h"
#include "lua/debug/lua_inspect_frames.h"
#include "sim/world.h"

namespace essaim {

namespace {
constexpr int kFramesPerThread = 10000;  // frame id = thread * this + level + 1 (0: no Lua frame)

Value Str(const std::string& s) { return Value::OfString(s); }
Value Int(long long i) { return Value::OfInteger(i); }

Value Capabilities() {
  Value caps = Value::EmptyMap();
  for (const char* name :
       {"supportsConfigurationDoneRequest", "supportsConditionalBreakpoints", "supportsHitConditionalBreakpoints",
        "supportsLogPoints", "supportsFunctionBreakpoints", "supportsStepBack", "supportsSetVariable",
        "supportsEvaluateForHovers", "supportsTerminateRequest"})
    caps.Set(name, Value::OfBool(true));
  Value filters = Value::EmptyList();
  filters.list.push_back(
      Value::MapOf({{"filter", Str("error")}, {"label", Str("Controller errors")}, {"default", Value::OfBool(false)}}));
  caps.Set("exceptionBreakpointFilters", std::move(filters));
  return caps;
}

Value SourceJson(const std::string& path) {
  return Value::MapOf({{"name", Str(std::filesystem::path(path).filename().string())}, {"path", Str(path)}});
}

std::string Canonical(const std::string& path) {
  std::error_code ec;
  const std::string c = std::filesystem::weakly_canonical(path, ec).string();
  return ec ? path : c;
}
}  // namespace

void DebugSession::Initialize(const Value& request) { channel_.Respond(request, Capabilities()); }

void DebugSession::Launch(const Value& request) {
  std::string error;
  DebugLaunch launch;
  launch_failed_ = !launcher_(ObjectField(request, "arguments"), &launch, &error);
  if (launch_failed_) {
    channel_.Respond(request, Value(), false, error);
    return;
  }
  launch_ = launch;
  launched_ = true;
  std::map<std::string, int> ids;
  if (launch_.lua_loop_functions) ids["loop functions"] = 1;
  for (size_t i = 0; i < launch_.robot_ids.size(); ++i) ids["robot " + launch_.robot_ids[i]] = static_cast<int>(i) + 2;
  debugger_.SetThreadIds(ids);
  std::error_code ec;
  debugger_.SetSourceBase(std::filesystem::current_path(ec).string());
  channel_.Respond(request, Value());
  channel_.Event("initialized", Value());
}

std::string DebugSession::FilePath(const std::string& path) const {
  std::filesystem::path p(path);
  if (p.is_relative()) p = std::filesystem::path(launch_.experiment_dir) / p;
  return Canonical(p.string());
}

// A controller or loop function runs the file: one of the model's scripts, or a Lua file
// beside or below one of them or the experiment (where `require` finds modules).
bool DebugSession::FileRuns(const std::string& canonical) const {
  if (std::find(launch_.scripts.begin(), launch_.scripts.end(), canonical) != launch_.scripts.end()) return true;
  if (!std::filesystem::exists(canonical)) return false;
  std::vector<std::string> roots = {launch_.experiment_dir};
  for (const std::string& s : launch_.scripts) roots.push_back(std::filesystem::path(s).parent_path().string());
  for (const std::string& root : roots)
    if (!root.empty() && canonical.rfind(root + "/", 0) == 0) return true;
  return false;
}

std::vector<LineBreakpoint> DebugSession::ApplyBreakpoints(const Value& args, std::string* file) {
  const std::string path = StringField(ObjectField(args, "source"), "path");
  *file = FilePath(path);
  asked_breakpoints_[path] = args;
  std::vector<LineBreakpoint> asked;
  if (const Value* list = args.Find("breakpoints"))
    for (const Value& b : list->list) {
      LineBreakpoint bp;
      bp.line = static_cast<int>(IntField(b, "line"));
      bp.condition = StringField(b, "condition");
      bp.hit_condition = StringField(b, "hitCondition");
      bp.log_message = StringField(b, "logMessage");
      asked.push_back(bp);
    }
  else if (const Value* lines = args.Find("lines"))  // the protocol's older form
    for (const Value& line : lines->list) {
      LineBreakpoint bp;
      bp.line = static_cast<int>(line.integer);
      asked.push_back(bp);
    }
  const std::string why_not = *file + ": no controller or loop function of this experiment runs this file";
  return debugger_.SetBreakpoints(*file, asked, FileRuns(*file), why_not);
}

void DebugSession::SetBreakpoints(const Value& request) {
  std::string file;
  const std::vector<LineBreakpoint> set = ApplyBreakpoints(ObjectField(request, "arguments"), &file);
  Value out = Value::EmptyList();
  for (const LineBreakpoint& bp : set) {
    Value b = Value::MapOf({{"id", Int(next_breakpoint_id_++)},
                            {"verified", Value::OfBool(bp.verified)},
                            {"line", Int(bp.actual_line)},
                            {"source", SourceJson(file)}});
    if (!bp.message.empty()) b.Set("message", Str(bp.message));
    out.list.push_back(std::move(b));
  }
  channel_.Respond(request, Value::MapOf({{"breakpoints", std::move(out)}}));
}

std::vector<FunctionBreakpoint> DebugSession::ApplyFunctionBreakpoints(const Value& args) {
  asked_functions_ = args;
  std::vector<FunctionBreakpoint> asked;
  if (const Value* list = args.Find("breakpoints"))
    for (const Value& b : list->list) {
      FunctionBreakpoint bp;
      bp.name = StringField(b, "name");
      bp.condition = StringField(b, "condition");
      bp.hit_condition = StringField(b, "hitCondition");
      asked.push_back(bp);
    }
  return debugger_.SetFunctionBreakpoints(asked);
}

bool DebugSession::ApplyExceptionBreakpoints(const Value& args) {
  asked_exceptions_ = args;
  bool on = false;
  if (const Value* filters = args.Find("filters"))
    for (const Value& f : filters->list) on = on || f.text == "error";
  debugger_.SetBreakOnError(on);
  return on;
}

void DebugSession::SetFunctionBreakpoints(const Value& request) {
  Value out = Value::EmptyList();
  for (const FunctionBreakpoint& bp : ApplyFunctionBreakpoints(ObjectField(request, "arguments"))) {
    Value b = Value::MapOf({{"id", Int(next_breakpoint_id_++)}, {"verified", Value::OfBool(bp.verified)}});
    if (!bp.message.empty()) b.Set("message", Str(bp.message));
    out.list.push_back(std::move(b));
  }
  channel_.Respond(request, Value::MapOf({{"breakpoints", std::move(out)}}));
}

void DebugSession::SetExceptionBreakpoints(const Value& request) {
  Value out = Value::EmptyList();
  if (ApplyExceptionBreakpoints(ObjectField(request, "arguments")))
    out.list.push_back(Value::MapOf({{"verified", Value::OfBool(true)}}));
  channel_.Respond(request, Value::MapOf({{"breakpoints", std::move(out)}}));
}

void DebugSession::Threads(const Value& request) {
  Value list = Value::EmptyList();
  if (launch_.lua_loop_functions) list.list.push_back(Value::MapOf({{"id", Int(1)}, {"name", Str("loop functions")}}));
  for (size_t i = 0; i < launch_.robot_ids.size(); ++i)
    list.list.push_back(
        Value::MapOf({{"id", Int(static_cast<long long>(i) + 2)}, {"name", Str(launch_.robot_ids[i])}}));
  channel_.Respond(request, Value::MapOf({{"threads", std::move(list)}}));
}

void DebugSession::StackTrace(const Value& request) {
  const int thread = static_cast<int>(IntField(ObjectField(request, "arguments"), "threadId"));
  last_thread_ = thread;
  Value frames = Value::EmptyList();
  if (!stop_.boundary && stop_.thread == thread) {
    for (const LuaFrame& f : LuaFrames(stop_.L, stop_.first_level)) {
      Value frame = Value::MapOf({{"id", Int(thread * kFramesPerThread + f.level + 1)},
                                  {"name", Str(f.name)},
                                  {"line", Int(f.line)},
                                  {"column", Int(1)}});
      if (!f.source.empty()) frame.Set("source", SourceJson(debugger_.CanonicalFile(f.source)));
      frames.list.push_back(std::move(frame));
    }
  }
  if (frames.list.empty()) {
    const std::string name = stop_.boundary ? "before tick " + std::to_string(BoundaryTick())
                                            : "tick " + std::to_string(debugger_.Tick()) + " (not in a call)";
    frames.list.push_back(Value::MapOf(
        {{"id", Int(thread * kFramesPerThread)}, {"name", Str(name)}, {"line", Int(0)}, {"column", Int(0)}}));
  }
  const long long total = static_cast<long long>(frames.list.size());
  const Value& args = ObjectField(request, "arguments");
  const auto start = static_cast<size_t>(std::clamp(IntField(args, "startFrame"), 0LL, total));
  const long long levels = IntField(args, "levels");
  frames.list.erase(frames.list.begin(), frames.list.begin() + static_cast<long>(start));
  if (levels > 0 && static_cast<size_t>(levels) < frames.list.size()) frames.list.resize(static_cast<size_t>(levels));
  channel_.Respond(request, Value::MapOf({{"stackFrames", std::move(frames)}, {"totalFrames", Int(total)}}));
}

void DebugSession::Scopes(const Value& request) {
  const long long frame = IntField(ObjectField(request, "arguments"), "frameId");
  const int thread = static_cast<int>(frame / kFramesPerThread);
  const int level = static_cast<int>(frame % kFramesPerThread) - 1;
  last_thread_ = thread;
  Value scopes = Value::EmptyList();
  auto add = [&](const char* name, Handle h) {
    scopes.list.push_back(Value::MapOf(
        {{"name", Str(name)}, {"variablesReference", Int(NewHandle(h))}, {"expensive", Value::OfBool(false)}}));
  };
  if (level >= 0) {
    add("Locals", {Handle::Kind::Locals, thread, level, -1});
    add("Upvalues", {Handle::Kind::Upvalues, thread, level, -1});
  }
  add("Globals", {Handle::Kind::Globals, thread, -1, -1});
  lua_State* L = StateFor(thread, -1);
  if (thread >= 2 && L) {
    const int ref = GlobalTableRef(L, "robot");
    if (ref >= 0) add("robot", {Handle::Kind::Table, thread, -1, ref});
  }
  channel_.Respond(request, Value::MapOf({{"scopes", std::move(scopes)}}));
}

Value DebugSession::VariableJson(int thread, const LuaVariable& v) {
  const int child = v.ref >= 0 ? NewHandle({Handle::Kind::Table, thread, -1, v.ref}) : 0;
  return Value::MapOf(
      {{"name", Str(v.name)}, {"value", Str(v.value)}, {"type", Str(v.type)}, {"variablesReference", Int(child)}});
}

void DebugSession::Variables(const Value& request) {
  const long long ref = IntField(ObjectField(request, "arguments"), "variablesReference");
  if (ref < 1 || ref > static_cast<long long>(handles_.size())) {
    channel_.Respond(request, Value(), false, "no such variablesReference (they last until the next resume)");
    return;
  }
  const Handle h = handles_[static_cast<size_t>(ref - 1)];
  last_thread_ = h.thread;  // the thread the user looks at (the live page rings its robot)
  lua_State* L = StateFor(h.thread, h.level);
  std::vector<LuaVariable> vars;
  if (L && h.kind == Handle::Kind::Locals) vars = FrameLocals(L, h.level);
  if (L && h.kind == Handle::Kind::Upvalues) vars = FrameUpvalues(L, h.level);
  if (L && h.kind == Handle::Kind::Globals) vars = UserGlobals(L);
  if (L && h.kind == Handle::Kind::Table) vars = TableEntries(L, h.ref);
  Value list = Value::EmptyList();
  for (const LuaVariable& v : vars) list.list.push_back(VariableJson(h.thread, v));
  channel_.Respond(request, Value::MapOf({{"variables", std::move(list)}}));
}

void DebugSession::Evaluate(const Value& request) {
  const Value& args = ObjectField(request, "arguments");
  int thread = last_thread_, level = -1;
  if (args.Find("frameId")) {
    const long long frame = IntField(args, "frameId");
    thread = static_cast<int>(frame / kFramesPerThread);
    level = static_cast<int>(frame % kFramesPerThread) - 1;
    last_thread_ = thread;
  } else if (stop_.active) {
    thread = stop_.thread;
  }
  lua_State* L = StateFor(thread, level);
  if (!L) {
    channel_.Respond(request, Value(), false, "no Lua state for thread " + std::to_string(thread));
    return;
  }
  const std::string expression = StringField(args, "expression");
  const bool repl = StringField(args, "context") == "repl";
  const LuaEvalResult r = EvaluateIn(L, level, expression, repl, debugger_.Tick());
  if (!r.ok) {
    channel_.Respond(request, Value(), false, r.error);
    return;
  }
  std::string error;
  if (repl && !CompilesAsExpression(L, expression, &error))  // a statement: it may change the run
    divergences_.push_back(Value::MapOf({{"tick", Int(debugger_.Tick())},
                                         {"thread", Str(ThreadName(thread))},
                                         {"name", Str("evaluate")},
                                         {"value", Str(expression)}}));
  Value v = VariableJson(thread, r.value);
  channel_.Respond(request, Value::MapOf({{"result", Str(r.value.value)},
                                          {"type", Str(r.value.type)},
                                          {"variablesReference", *v.Find("variablesReference")}}));
}

void DebugSession::SetVariable(const Value& request) {
  const Value& args = ObjectField(request, "arguments");
  const long long ref = IntField(args, "variablesReference");
  if (ref < 1 || ref > static_cast<long long>(handles_.size())) {
    channel_.Respond(request, Value(), false, "no such variablesReference");
    return;
  }
  const Handle h = handles_[static_cast<size_t>(ref - 1)];
  static const VariableScope scopes[] = {VariableScope::Locals, VariableScope::Upvalues, VariableScope::Globals,
                                         VariableScope::Table};
  const std::string name = StringField(args, "name"), value = StringField(args, "value");
  lua_State* L = StateFor(h.thread, h.level);
  LuaVariable result;
  std::string error;
  if (!L || !SetVariableIn(L, scopes[static_cast<int>(h.kind)], h.level, h.ref, name, value, debugger_.Tick(), &result,
                           &error)) {
    channel_.Respond(request, Value(), false, L ? error : "no Lua state for this thread");
    return;
  }
  divergences_.push_back(Value::MapOf({{"tick", Int(debugger_.Tick())},
                                       {"thread", Str(ThreadName(h.thread))},
                                       {"name", Str(name)},
                                       {"value", Str(value)}}));
  Value v = VariableJson(h.thread, result);
  channel_.Respond(request, Value::MapOf({{"value", Str(result.value)},
                                          {"type", Str(result.type)},
                                          {"variablesReference", *v.Find("variablesReference")}}));
}

DebugSession::After DebugSession::Resume(const Value& request, StepMode mode) {
  const int thread = static_cast<int>(IntField(ObjectField(request, "arguments"), "threadId", stop_.thread));
  if (mode == StepMode::None)
    debugger_.Resume(StepMode::None, 0, nullptr);
  else if (!stop_.boundary && stop_.thread == thread)
    debugger_.Resume(mode, thread, stop_.L);
  else  // from a tick boundary, or a thread not in a call: its next call's first line
    debugger_.Resume(StepMode::In, thread, nullptr);
  last_thread_ = thread;
  channel_.Respond(request,
                   mode == StepMode::None ? Value::MapOf({{"allThreadsContinued", Value::OfBool(true)}}) : Value());
  return After::Resume;
}

DebugSession::After DebugSession::RunToTick(const Value& request) {
  const long long tick = IntField(ObjectField(request, "arguments"), "tick");
  const long long now = stop_.boundary ? BoundaryTick() : debugger_.Tick() + 1;
  if (tick < 1) {
    channel_.Respond(request, Value(), false, "runToTick: tick must be >= 1");
    return After::Stay;
  }
  if (tick < now || (tick == now && stop_.boundary)) {
    if (!checkpoints_ || checkpoints_->NewestAtOrBefore(tick - 1) < 0) {
      channel_.Respond(request, Value(), false, "runToTick: cannot go back in this session");
      return After::Stay;
    }
    channel_.Respond(request, Value());
    Replay target;
    target.kind = "boundary";
    target.at.tick = tick;
    target.thread = last_thread_ ? last_thread_ : stop_.thread;
    target.reason = "goto";
    target.description = "before tick " + std::to_string(tick);
    GoTo(target, tick - 1);
  }
  run_to_tick_ = tick;
  debugger_.Resume(StepMode::None, 0, nullptr);
  channel_.Respond(request, Value());
  return After::Resume;
}

void DebugSession::Pause(const Value& request) {
  int thread = static_cast<int>(IntField(ObjectField(request, "arguments"), "threadId"));
  if (thread <= 0) thread = launch_.robot_ids.empty() ? 1 : 2;
  if (!stop_.active) pause_thread_ = thread;
  channel_.Respond(request, Value());
}

DebugSession::After DebugSession::Terminate(const Value& request) {
  terminate_ = true;
  debugger_.Detach();
  channel_.Respond(request, Value());
  return After::Resume;
}

DebugSession::After DebugSession::Disconnect(const Value& request) {
  const bool terminate = BoolField(ObjectField(request, "arguments"), "terminateDebuggee", true);
  debugger_.Detach();
  channel_.Respond(request, Value());
  detached_ = true;  // no more events: the client is gone
  terminate_ = terminate;
  return After::Resume;
}

}  // namespace essaim
