// The recording reader behind `essaim replay`, `essaim snapshot` and `essaim video` (the
// header parser is the streaming reader's too), then a small snapshot of its last frame when
// Cairo is built in (the renderer once spun forever on damaged geometry), and a video's frame:
// a view around the first robot, the tick, ids and scale bar.
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
  FrameRenderer renderer(rec.scene(), 64, 48);
  DrawOptions draw;
  draw.tick = draw.ids = draw.scale_bar = true;
  const RecordedRobot first = rec.RobotCount() > 0 ? rec.Robot(frames - 1, 0) : RecordedRobot{};
  draw.view_size = Vec2(3, 2.25);
  draw.view_min = Vec2(first.x, first.y) - draw.view_size / 2;
  renderer.Draw({rec.Frame(0), rec.Frame(frames - 1)}, draw, &error);
#endif
  return 0;
}
