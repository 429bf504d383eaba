#include "lua/debug/lua_debugger.h"

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <lua.hpp>

#include "lua/debug/chunk_lines.h"
#include "lua/debug/lua_inspect_frames.h"

namespace essaim {

namespace {
LuaGuard* GuardOfState(lua_State* L) {
  void* ud = nullptr;
  lua_getallocf(L, &ud);
  return static_cast<LuaGuard*>(ud);
}

int Depth(lua_State* L) {
  lua_Debug ar;
  int depth = 0;
  while (lua_getstack(L, depth, &ar)) ++depth;
  return depth;
}

std::string Trim(const std::string& s) {
  size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}
}  // namespace

bool HitConditionPasses(const std::string& condition, long long hits, bool* passes, std::string* error) {
  std::string c = Trim(condition);
  std::string op = ">=";
  for (const char* o : {">=", "<=", "==", ">", "<", "%", "="})
    if (c.rfind(o, 0) == 0) {
      op = o;
      c = Trim(c.substr(std::string(o).size()));
      break;
    }
  char* end = nullptr;
  const long long n = std::strtoll(c.c_str(), &end, 10);
  if (c.empty() || *end != '\0' || n < 0 || (op == "%" && n == 0)) {
    *error = "hitCondition '" + condition + "' must be a number N (break from the Nth hit on), >=N, or %N";
    return false;
  }
  if (op == ">=") *passes = hits >= n;
  if (op == ">") *passes = hits > n;
  if (op == "<=") *passes = hits <= n;
  if (op == "<") *passes = hits < n;
  if (op == "==" || op == "=") *passes = hits == n;
  if (op == "%") *passes = hits % n == 0;
  return true;
}

const LuaDebugger::Thread* LuaDebugger::FindThread(int id) const {
  for (const auto& [guard, t] : threads_)
    if (t.id == id) return &t;
  return nullptr;
}

std::vector<const LuaDebugger::Thread*> LuaDebugger::Threads() const {
  std::vector<const Thread*> out;
  for (const auto& [guard, t] : threads_) out.push_back(&t);
  return out;
}

void LuaDebugger::StateOpened(lua_State* L, LuaGuard* guard) {
  auto id = ids_.find(guard->name);
  if (id == ids_.end()) return;  // a state the session does not show (none today)
  Thread& t = threads_[guard];
  t.id = id->second;
  t.name = guard->name.rfind("robot ", 0) == 0 ? guard->name.substr(6) : guard->name;
  t.guard = guard;
  t.L = L;
  SetDebugMask(guard, MaskFor(t));
}

void LuaDebugger::StateClosed(LuaGuard* guard) { threads_.erase(guard); }

LuaDebugger::Thread* LuaDebugger::ThreadOf(lua_State* L) {
  auto found = threads_.find(GuardOfState(L));
  return found == threads_.end() ? nullptr : &found->second;
}

int LuaDebugger::MaskFor(const Thread& t) const {
  if (detached_) return 0;
  int mask = 0;
  if (!breakpoint_lines_.empty() || entry_thread_ == t.id) mask |= LUA_MASKLINE;
  if (step_.mode != StepMode::None && step_.thread == t.id) mask |= LUA_MASKLINE;
  if (!function_breakpoints_.empty()) mask |= LUA_MASKCALL | LUA_MASKLINE;
  return mask;
}

void LuaDebugger::UpdateMasks() {
  for (auto& [guard, t] : threads_) SetDebugMask(guard, MaskFor(t));
}

std::vector<LineBreakpoint> LuaDebugger::SetBreakpoints(const std::string& file, std::vector<LineBreakpoint> bps,
                                                        bool runs, const std::string& why_not) {
  std::set<int> lines;
  std::string error;
  const bool loads = runs && ActiveLinesOfFile(file, &lines, &error);
  lua_State* scratch = luaL_newstate();
  for (LineBreakpoint& bp : bps) {
    bp.actual_line = bp.line;
    bp.verified = false;
    bp.hits = 0;
    if (!runs) {
      bp.message = why_not;
      continue;
    }
    if (!loads) {
      bp.message = error;
      continue;
    }
    bp.actual_line = NextActiveLine(lines, bp.line);
    bool passes = false;
    if (bp.actual_line == 0) {
      bp.actual_line = bp.line;
      bp.message = "no code at or after line " + std::to_string(bp.line);
    } else if (!bp.condition.empty() && !CompilesAsExpression(scratch, bp.condition, &error)) {
      bp.message = "condition: " + error;
    } else if (!bp.hit_condition.empty() && !HitConditionPasses(bp.hit_condition, 0, &passes, &error)) {
      bp.message = error;
    } else {
      bp.verified = true;
    }
  }
  lua_close(scratch);
  std::vector<LineBreakpoint>& kept = breakpoints_[file];
  kept.clear();
  for (const LineBreakpoint& bp : bps)
    if (bp.verified) kept.push_back(bp);
  if (kept.empty()) breakpoints_.erase(file);
  breakpoint_lines_.clear();
  for (const auto& [f, list] : breakpoints_)
    for (const LineBreakpoint& bp : list) breakpoint_lines_.insert(bp.actual_line);
  UpdateMasks();
  return bps;
}

std::vector<FunctionBreakpoint> LuaDebugger::SetFunctionBreakpoints(std::vector<FunctionBreakpoint> bps) {
  static const std::set<std::string> known = {"step", "init", "reset", "destroy"};
  lua_State* scratch = luaL_newstate();
  function_breakpoints_.clear();
  for (FunctionBreakpoint& bp : bps) {
    std::string error;
    bool passes = false;
    bp.verified = false;
    if (!known.count(bp.name))
      bp.message = "'" + bp.name + "' is not a controller function: step, init, reset or destroy";
    else if (!bp.condition.empty() && !CompilesAsExpression(scratch, bp.condition, &error))
      bp.message = "condition: " + error;
    else if (!bp.hit_condition.empty() && !HitConditionPasses(bp.hit_condition, 0, &passes, &error))
      bp.message = error;
    else
      bp.verified = true;
    if (bp.verified) function_breakpoints_.push_back(bp);
  }
  lua_close(scratch);
  UpdateMasks();
  return bps;
}

void LuaDebugger::Resume(StepMode mode, int thread, lua_State* L) {
  step_ = Stepping();
  step_.mode = mode;
  step_.thread = thread;
  step_.depth = L ? Depth(L) : 0;
  step_.tick = tick_;
  UpdateMasks();
}

void LuaDebugger::Detach() {
  detached_ = true;
  step_ = Stepping();
  UpdateMasks();
}

std::string LuaDebugger::CanonicalFile(const std::string& path) const {
  std::filesystem::path p(path);
  if (p.is_relative() && !source_base_.empty()) p = std::filesystem::path(source_base_) / p;
  std::error_code ec;
  const std::string canonical = std::filesystem::weakly_canonical(p, ec).string();
  return ec ? p.string() : canonical;
}

const std::string& LuaDebugger::CanonicalSource(const char* source) {
  auto found = canonical_.find(source);
  if (found != canonical_.end()) return found->second;
  return canonical_[source] = source[0] == '@' ? CanonicalFile(source + 1) : std::string();
}

std::string LuaDebugger::Prefix(const Thread& t) const { return t.name + " tick " + std::to_string(tick_) + ": "; }

bool LuaDebugger::ConditionHolds(lua_State* L, const std::string& condition, const Thread& t) {
  if (condition.empty()) return true;
  bool truth = false;
  std::string error;
  if (EvaluateTruth(L, 0, condition, tick_, &truth, &error)) return truth;
  if (!quiet_) listener_->Console(Prefix(t) + "condition error: " + error + "\n");
  return false;
}

// {expr} replaced by the expression's value; {{ and }} are braces.
namespace {
std::string Interpolate(lua_State* L, const std::string& message, long long tick) {
  std::string out;
  for (size_t i = 0; i < message.size(); ++i) {
    const size_t close = message[i] == '{' ? message.find('}', i) : std::string::npos;
    if (close == std::string::npos) {
      out += message[i];
      continue;
    }
    std::string text, error;
    out += EvaluateText(L, 0, message.substr(i + 1, close - i - 1), tick, &text, &error) ? text : "<" + error + ">";
    i = close;
  }
  return out;
}
}  // namespace

bool LuaDebugger::BreakpointFires(lua_State* L, const std::string& file, int line, Thread* t) {
  auto found = breakpoints_.find(file);
  if (found == breakpoints_.end()) return false;
  bool fires = false;
  for (LineBreakpoint& bp : found->second) {
    if (bp.actual_line != line || !ConditionHolds(L, bp.condition, *t)) continue;
    ++bp.hits;
    bool passes = true;
    std::string error;
    if (!bp.hit_condition.empty()) HitConditionPasses(bp.hit_condition, bp.hits, &passes, &error);
    if (!passes) continue;
    if (!bp.log_message.empty()) {
      if (!quiet_) listener_->Console(Prefix(*t) + Interpolate(L, bp.log_message, tick_) + "\n");
      continue;
    }
    if (fires) continue;
    fires = true;
    if (t->fires_tick != tick_) t->fires_tick = tick_, t->fires = 0;
    ++t->fires;
    if (listener_->Fired({tick_, SlotOf(t->id), t->fires})) quiet_ = false;  // a going back's target
  }
  return fires && !quiet_;
}

bool LuaDebugger::StepDone(lua_State* L) const {
  if (step_.tick != tick_) return true;  // past the end of the call: the next one's first line
  switch (step_.mode) {
    case StepMode::In:
      return true;
    case StepMode::Over:
      return Depth(L) <= step_.depth;
    case StepMode::Out:
      return Depth(L) < step_.depth;
    case StepMode::None:
      break;
  }
  return false;
}

void LuaDebugger::OnCall(lua_State* L, Thread* t) {
  lua_Debug ar;
  if (!lua_getstack(L, 0, &ar)) return;
  lua_getinfo(L, "f", &ar);
  for (size_t i = 0; i < function_breakpoints_.size(); ++i) {
    lua_getglobal(L, function_breakpoints_[i].name.c_str());
    const bool same = lua_rawequal(L, -1, -2);
    lua_pop(L, 1);
    if (same) t->pending_function = static_cast<int>(i);
  }
  lua_pop(L, 1);
}

void LuaDebugger::OnLine(lua_State* L, lua_Debug* ar, Thread* t) {
  if (t->pending_function >= 0) {
    FunctionBreakpoint& bp = function_breakpoints_[static_cast<size_t>(t->pending_function)];
    t->pending_function = -1;
    bool passes = true;
    std::string error;
    if (ConditionHolds(L, bp.condition, *t)) {
      ++bp.hits;
      if (!bp.hit_condition.empty()) HitConditionPasses(bp.hit_condition, bp.hits, &passes, &error);
      if (passes) return Stop(t, L, {"function breakpoint", "function breakpoint on " + bp.name, "", 0});
    }
  }
  if (step_.mode != StepMode::None && step_.thread == t->id && StepDone(L)) return Stop(t, L, {"step", "step", "", 0});
  if (!breakpoint_lines_.count(ar->currentline)) return;
  lua_getinfo(L, "S", ar);
  if (BreakpointFires(L, CanonicalSource(ar->source), ar->currentline, t))
    Stop(t, L, {"breakpoint", "breakpoint", "", 0});
}

// Robots run in model order (thread i + 2); the loop functions before them (pre_step) or after
// them (post_step).
long long LuaDebugger::SlotOf(int thread) const {
  if (thread >= 2) return thread;
  return robots_ran_tick_ == tick_ ? (1LL << 40) : 1;
}

RunPosition LuaDebugger::PositionOf(int thread) const {
  const Thread* t = FindThread(thread);
  return {tick_, SlotOf(thread), t && t->fires_tick == tick_ ? t->fires : 0};
}

void LuaDebugger::SetEntryTarget(int thread, long long tick) {
  entry_thread_ = thread;
  entry_tick_ = tick;
  UpdateMasks();
}

void LuaDebugger::ForgetWatchdog() {
  for (auto& [guard, t] : threads_) guard->watchdog = nullptr;
}

void LuaDebugger::Hook(lua_State* L, lua_Debug* ar) {
  if (detached_) return;
  Thread* t = ThreadOf(L);
  if (!t) return;
  if (t->id >= 2) robots_ran_tick_ = tick_;
  if (entry_thread_ == t->id && tick_ == entry_tick_ && ar->event == LUA_HOOKLINE) {
    entry_thread_ = 0;
    return Stop(t, L, {"step", "step back", "", 0});
  }
  // Quiet (re-simulating to a going back's target): breakpoints are still counted.
  if (quiet_) {
    if (ar->event == LUA_HOOKLINE && breakpoint_lines_.count(ar->currentline)) {
      lua_getinfo(L, "S", ar);
      if (BreakpointFires(L, CanonicalSource(ar->source), ar->currentline, t))
        Stop(t, L, {"breakpoint", "breakpoint", "", 0});
    }
    return;
  }
  if (ar->event == LUA_HOOKCALL) {
    if (!function_breakpoints_.empty()) OnCall(L, t);
    return;
  }
  if (ar->event == LUA_HOOKLINE) OnLine(L, ar, t);
}

void LuaDebugger::Raised(lua_State* L, const char* message) {
  if (!break_on_error_ || quiet_ || detached_) return;
  Thread* t = ThreadOf(L);
  const int level = FirstLuaLevel(L, 0);
  if (!t || level < 0) return;
  Stop(t, L, {"exception", "error", message ? message : "error", level});
}

void LuaDebugger::Stop(Thread* t, lua_State* L, StopInfo why) {
  step_ = Stepping();
  quiet_ = true;  // what the client evaluates while stopped never stops
  listener_->Stopped(t->id, L, why);
  quiet_ = false;
  UpdateMasks();
}

}  // namespace essaim
