#include "sim/loop_hooks.h"

#include "sim/stepping.h"

namespace essaim {

bool CallLoopHook(World& w, const char* hook, std::string* error) {
  const SteppingScope stepping(kSteppingLoopFunctions, hook);
  if (w.cpp_loop_functions.Loaded()) return w.cpp_loop_functions.Call(hook, error);
  return w.loop_functions.Call(hook, error);
}

bool LoopExperimentFinished(World& w, bool* finished, std::string* error) {
  if (w.cpp_loop_functions.Loaded()) return w.cpp_loop_functions.IsExperimentFinished(finished, error);
  return w.loop_functions.IsExperimentFinished(finished, error);
}

LoopEnd LoopFunctionsEnd(World& w) {
  if (w.cpp_loop_functions.Loaded()) return LoopEnd::kUnknown;
  if (!w.loop_functions.Loaded()) return LoopEnd::kNone;
  return w.loop_functions.HasFunction("is_experiment_finished") ? LoopEnd::kFunction : LoopEnd::kNoFunction;
}

bool LoopPostExperiment(World& w, Value* metrics, bool* has_metrics, std::string* error) {
  if (!w.cpp_loop_functions.Loaded()) return w.loop_functions.PostExperiment(metrics, has_metrics, error);
  *has_metrics = false;
  return w.cpp_loop_functions.Call("post_experiment", error);
}

void SetLoopTick(World& w) {
  if (w.argos.Loaded()) w.argos.SetTick(w.tick);
  w.loop_functions.SetTick(w.tick);
}

void FlushLoopLog(World& w) {
  if (w.cpp_loop_functions.Loaded()) FlushLog(w, w.cpp_loop_functions.LogBuffer(), kLogLoopFunctions);
  FlushLog(w, w.loop_functions.LogBuffer(), kLogLoopFunctions);
}

bool DrawLoopFloor(World& w, std::string* error) {
  FloorRaster& f = w.floor;
  const bool cpp = w.cpp_loop_functions.Loaded();
  for (int py = 0; py < f.height; ++py)
    for (int px = 0; px < f.width; ++px) {
      const double x = f.min.x() + (px + 0.5) * f.size.x() / f.width;
      const double y = f.min.y() + (py + 0.5) * f.size.y() / f.height;
      Color* pixel = &f.pixels[static_cast<size_t>(py) * f.width + px];
      const bool ok =
          cpp ? w.cpp_loop_functions.FloorColor(x, y, pixel, error) : w.loop_functions.FloorColor(x, y, pixel, error);
      if (!ok) return false;
    }
  return true;
}

bool TakeFloorChanged(World& w) {
  if (w.cpp_loop_functions.Loaded()) return w.cpp_loop_functions.TakeFloorChanged();
  return w.loop_functions.Loaded() && w.loop_functions.TakeFloorChanged();
}

bool RedrawFloorIfChanged(World& w, std::string* error) {
  if (!TakeFloorChanged(w) || w.model.floor.source != FloorSource::LoopFunctions) return true;
  return DrawLoopFloor(w, error);
}

bool DestroyLoopFunctions(World& w, std::string* error) {
  if (!w.cpp_loop_functions.Loaded() && !w.loop_functions.Loaded()) return true;
  const bool ok = CallLoopHook(w, "destroy", error);
  FlushLoopLog(w);
  return ok;
}

}  // namespace essaim
