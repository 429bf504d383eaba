// Going back: stepBack, reverseContinue and runToTick behind the current position, by
// waking a checkpoint (checkpoints.h) whose copy re-simulates silently to the target. A
// reverseContinue first searches: the copy re-simulates to the current position noting the
// breakpoints that fire, then goes to the last one (or searches before its checkpoint).
#include <unistd.h>

#include "core/value_json.h"
#include "debug/debug_session.h"
#include "sim/world.h"

namespace essaim {

void DebugSession::EnableGoingBack(pid_t front, const FrontLink& link) {
  checkpoints_ = std::make_unique<Checkpoints>(front);
  front_ = link;
}

void DebugSession::EndCheckpoints() {
  if (checkpoints_) checkpoints_->EndAll();
}

bool DebugSession::Fired(const RunPosition& where) {
  if (!replay_.active) return false;
  if (replay_.kind == "fire") return where == replay_.at;
  if (replay_.kind == "search" && where < replay_.at) {
    replay_.found = true;
    replay_.found_at = where;
  }
  return false;
}

void DebugSession::GoBack(const Value& request) {
  if (!checkpoints_ || checkpoints_->Count() == 0) {
    channel_.Respond(request, Value(), false, "going back is not available in this session");
    return;
  }
  const bool step_back = StringField(request, "command") == "stepBack";
  const int thread = static_cast<int>(IntField(ObjectField(request, "arguments"), "threadId", stop_.thread));
  channel_.Respond(request, Value());
  Replay target;
  target.thread = thread;
  const long long now = stop_.boundary ? BoundaryTick() : debugger_.Tick();
  if (step_back && now - 1 >= 1) {
    target.kind = "entry";
    target.at.tick = now - 1;
    GoTo(target, now - 2);
  }
  if (!step_back) {
    // Where the client stands: a hit before it is a breakpoint fired earlier in the run.
    target.kind = "search";
    target.at = {now, 0, 0};
    if (!stop_.boundary) target.at = debugger_.PositionOf(stop_.thread);
    if (!stop_.boundary && stop_.reason != "breakpoint") ++target.at.fire;  // its last fire is behind
    const long long checkpoint = stop_.boundary ? now - 2 : now - 1;
    if (checkpoint >= 0) GoTo(target, checkpoint);
  }
  target.kind = "boundary";  // nothing earlier: the start
  target.at = {1, 0, 0};
  target.reason = step_back ? "step" : "entry";
  target.description = "before tick 1";
  GoTo(target, 0);
}

Value DebugSession::OrderFor(const Replay& target) const {
  Value breakpoints = Value::EmptyMap();
  for (const auto& [path, args] : asked_breakpoints_) breakpoints.Set(path, args);
  return Value::MapOf(
      {{"kind", Value::OfString(target.kind)},
       {"tick", Value::OfInteger(target.at.tick)},
       {"slot", Value::OfInteger(target.at.slot)},
       {"fire", Value::OfInteger(target.at.fire)},
       {"thread", Value::OfInteger(target.thread)},
       {"reason", Value::OfString(target.reason)},
       {"description", Value::OfString(target.description)},
       {"seq", Value::OfInteger(channel_.Seq())},
       {"unread", Value::OfString(channel_.Unread())},
       {"breakpoints", std::move(breakpoints)},
       {"functions", asked_functions_},
       {"exceptions", asked_exceptions_},
       {"divergences", Value::OfInteger(static_cast<long long>(std::max(divergences_.size(), target.divergences)))},
       {"last_thread", Value::OfInteger(last_thread_)}});
}

void DebugSession::GoTo(const Replay& target, long long checkpoint_tick) {
  int index = checkpoints_->NewestAtOrBefore(checkpoint_tick);
  if (index < 0) index = 0;
  checkpoints_->Wake(index, ValueJsonLine(OrderFor(target)));
  _exit(0);  // the woken copy is the simulation now; nothing of this one is written
}

void DebugSession::TakeOrder(const std::string& text) {
  Value o;
  std::string error;
  ParseJsonValue(text, &o, &error);
  debugger_.ForgetWatchdog();
  TellFrontLive(front_);
  channel_.SetSeq(IntField(o, "seq"));
  channel_.SetUnread(StringField(o, "unread"));
  asked_breakpoints_.clear();
  std::string file;
  for (const auto& [path, args] : ObjectField(o, "breakpoints").map) ApplyBreakpoints(args, &file);
  if (o.Find("functions") && !o.Find("functions")->IsNull()) ApplyFunctionBreakpoints(*o.Find("functions"));
  if (o.Find("exceptions") && !o.Find("exceptions")->IsNull()) ApplyExceptionBreakpoints(*o.Find("exceptions"));
  replay_ = Replay();
  replay_.active = true;
  replay_.kind = StringField(o, "kind");
  replay_.at = {IntField(o, "tick"), IntField(o, "slot"), IntField(o, "fire")};
  replay_.thread = static_cast<int>(IntField(o, "thread"));
  replay_.reason = StringField(o, "reason");
  replay_.description = StringField(o, "description");
  replay_.divergences = static_cast<size_t>(IntField(o, "divergences"));
  replay_.from_tick = world_ ? static_cast<long long>(world_->tick) : 0;
  last_thread_ = static_cast<int>(IntField(o, "last_thread"));
  launch_.stop_on_entry = false;
  pause_thread_ = 0;
  run_to_tick_ = 0;
  debugger_.Resume(StepMode::None, 0, nullptr);
  debugger_.SetQuiet(true);
  if (replay_.kind == "entry") debugger_.SetEntryTarget(replay_.thread, replay_.at.tick);
}

// At a boundary while re-simulating: the target reached (a stop), a search concluded, or
// simply on. True when it stopped here.
bool DebugSession::ReplayBoundary() {
  const long long next = BoundaryTick();
  if (replay_.kind == "boundary" && next == replay_.at.tick) {
    BoundaryStop(replay_.reason, replay_.thread, replay_.description);
    return true;
  }
  if (replay_.kind == "search" && next > replay_.at.tick) ConcludeSearch();
  if (replay_.kind == "entry" && next > replay_.at.tick) {
    // The robot did not run at that tick (it died, or its controller failed): the boundary
    // before it instead.
    Replay target = replay_;
    target.kind = "boundary";
    target.reason = "step";
    target.description = "before tick " + std::to_string(replay_.at.tick);
    GoTo(target, replay_.at.tick - 1);
  }
  if (replay_.kind == "fire" && next > replay_.at.tick) {  // never expected: a run is deterministic
    BoundaryStop("breakpoint", replay_.thread, "before tick " + std::to_string(next));
    return true;
  }
  return false;
}

void DebugSession::ConcludeSearch() {
  Replay target = replay_;
  if (replay_.found) {
    target.kind = "fire";
    target.at = replay_.found_at;
    GoTo(target, replay_.found_at.tick - 1);
  }
  const long long from = replay_.from_tick;
  if (from <= 0 || checkpoints_->NewestAtOrBefore(from - 1) < 0) {
    target.kind = "boundary";
    target.at = {1, 0, 0};
    target.reason = "entry";
    target.description = "before tick 1";
    GoTo(target, 0);
  }
  target.at = {from + 1, 0, 0};  // every fire up to the checkpoint's tick
  target.found = false;
  GoTo(target, from - 1);
}

void DebugSession::FinishReplay() {
  replay_.active = false;
  debugger_.SetQuiet(false);
  debugger_.SetEntryTarget(0, 0);
  if (replay_.divergences > divergences_.size())
    Console("going back dropped " + std::to_string(replay_.divergences - divergences_.size()) +
            " change(s) made by hand: the run is the undiverged one again\n");
}

}  // namespace essaim
