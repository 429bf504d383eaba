// The recording reader behind `essaim replay` and `essaim snapshot`, then a small snapshot
// of its first and last frames when Cairo is built in (the renderer once spun forever on
// damaged geometry).
#include <cmath>
#include <cstdint>
#include <string>

#include "output/recording.h"
#ifdef ESSAIM_HAVE_CAIRO
#include "render/render_cairo.h"
#endif

using namespace essaim;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Recording rec;
  std::string error;
  if (!Recording::Parse(std::string(reinterpret_cast<const char*>(data), size), &rec, &error)) return 0;
  const size_t frames = rec.FrameCount();
  for (size_t f : {size_t{0}, frames - 1}) {
    rec.Tick(f);
    for (size_t r = 0; r < rec.RobotCount(); ++r)
      if (!std::isfinite(rec.Robot(f, r).x)) __builtin_trap();
    for (size_t k = 0; k < rec.scene().movable.size(); ++k) rec.Movable(f, k);
  }
  rec.FrameAtOrBefore(rec.Tick(frames - 1));
#ifdef ESSAIM_HAVE_CAIRO
  SnapshotOptions opt;
  opt.size = 64;
  opt.trail_ticks = 1000;
  std::string png;
  RenderSnapshotPng(rec, frames - 1, opt, &png, &error);
#endif
  return 0;
}
