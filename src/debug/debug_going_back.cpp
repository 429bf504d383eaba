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

bool DebugSession::Fired(long long tick, long long index) {
  if (!replay_.active) return false;
  if (replay_.kind == "fire") return tick == replay_.tick && index == replay_.fire;
  if (replay_.kind == "search" && (tick < replay_.tick || (tick == replay_.tick && index < replay_.fire))) {
    replay_.found_tick = tick;
    replay_.found_fire = index;
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
    target.tick = now - 1;
    GoTo(target, now - 2);
  }
  if (!step_back) {
    // Where the client stands, as (tick, breakpoints fired before it in that tick + 1).
    target.kind = "search";
    target.tick = now;
    target.fire = stop_.boundary ? 0 : debugger_.FiresThisTick() + (stop_.reason == "breakpoint" ? 0 : 1);
    const long long checkpoint = target.fire == 0 ? now - 2 : now - 1;
    if (checkpoint >= 0) GoTo(target, checkpoint);
  }
  target.kind = "boundary";  // nothing earlier: the start
  target.tick = 1;
  target.reason = step_back ? "step" : "entry";
  target.description = "before tick 1";
  GoTo(target, 0);
}

Value DebugSession::OrderFor(const Replay& target) const {
  Value breakpoints = Value::EmptyMap();
  for (const auto& [path, args] : asked_breakpoints_) breakpoints.Set(path, args);
  return Value::MapOf(
      {{"kind", Value::OfString(target.kind)},
       {"tick", Value::OfInteger(target.tick)},
       {"fire", Value::OfInteger(target.fire)},
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
  replay_.tick = IntField(o, "tick");
  replay_.fire = IntField(o, "fire");
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
  if (replay_.kind == "entry") debugger_.SetEntryTarget(replay_.thread, replay_.tick);
}

// At a boundary while re-simulating: the target reached (a stop), a search concluded, or
// simply on. True when it stopped here.
bool DebugSession::ReplayBoundary() {
  const long long next = BoundaryTick();
  if (replay_.kind == "boundary" && next == replay_.tick) {
    BoundaryStop(replay_.reason, replay_.thread, replay_.description);
    return true;
  }
  if (replay_.kind == "search" && next > replay_.tick) ConcludeSearch();
  if (replay_.kind == "entry" && next > replay_.tick) {
    // The robot did not run at that tick (it died, or its controller failed): the boundary
    // before it instead.
    Replay target = replay_;
    target.kind = "boundary";
    target.reason = "step";
    target.description = "before tick " + std::to_string(replay_.tick);
    GoTo(target, replay_.tick - 1);
  }
  if (replay_.kind == "fire" && next > replay_.tick) {  // never expected: a run is deterministic
    BoundaryStop("breakpoint", replay_.thread, "before tick " + std::to_string(next));
    return true;
  }
  return false;
}

void DebugSession::ConcludeSearch() {
  Replay target = replay_;
  if (replay_.found_tick >= 0) {
    target.kind = "fire";
    target.tick = replay_.found_tick;
    target.fire = replay_.found_fire;
    GoTo(target, replay_.found_tick - 1);
  }
  const long long from = replay_.from_tick;
  if (from <= 0 || checkpoints_->NewestAtOrBefore(from - 1) < 0) {
    target.kind = "boundary";
    target.tick = 1;
    target.reason = "entry";
    target.description = "before tick 1";
    GoTo(target, 0);
  }
  target.tick = from + 1;  // every fire up to the checkpoint's tick
  target.fire = 0;
  target.found_tick = -1;
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
