// The experiment's loop functions, Lua (lua/loop) or C++ (argos/), whichever the model
// names: the stages call these, so both run at the same points of the tick.
#pragma once
#include <string>

#include "core/value.h"
#include "sim/world.h"

namespace essaim {

/// "init", "pre_step", "post_step", "reset", "destroy".
bool CallLoopHook(World& w, const char* hook, std::string* error);
bool LoopExperimentFinished(World& w, bool* finished, std::string* error);
/// Whether the loop functions can end the run: none loaded, Lua ones with no
/// is_experiment_finished(), Lua ones with it, or C++ ones (whose IsExperimentFinished is a
/// virtual that cannot be seen overridden or not).
enum class LoopEnd { kNone, kNoFunction, kFunction, kUnknown };
LoopEnd LoopFunctionsEnd(World& w);
/// post_experiment(); Lua's returned table becomes `metrics` (C++ ones write their own files).
bool LoopPostExperiment(World& w, Value* metrics, bool* has_metrics, std::string* error);
void SetLoopTick(World& w);
/// Hands the loop functions' log lines to the log sink.
void FlushLoopLog(World& w);
/// Samples the loop functions' floor colour into w.floor (its size already set).
bool DrawLoopFloor(World& w, std::string* error);
/// Whether the loop functions said the floor changed since the last call (and forgets it).
bool TakeFloorChanged(World& w);
/// Draws the floor again when the loop functions said it changed (C++: the floor entity's
/// SetChanged(); Lua: experiment.floor_changed()).
bool RedrawFloorIfChanged(World& w, std::string* error);
/// The loop functions' destroy() / Destroy(), at the end of a run (as ARGoS's
/// CSimulator::Destroy, before the space and its controllers go), its log flushed.
bool DestroyLoopFunctions(World& w, std::string* error);

}  // namespace essaim
