// `essaim snapshot RUN_DIR --tick T -o FILE.png [--trail N] [--size PX]`: one frame of a
// recorded run as a PNG (docs/replay.md), drawn by render/render_cairo.cpp.
#include <algorithm>
#include <cstdio>
#include <memory>

#include "app/cli_support.h"
#include "app/commands.h"
#include "core/paths.h"
#include "core/strings.h"
#include "output/atomic_file.h"
#include "output/recording.h"
#ifdef ESSAIM_HAVE_CAIRO
#include "render/render_cairo.h"
#endif

namespace essaim {

namespace {

struct SnapshotArgs {
  std::string run, out;
  long long tick = -1;  // -1: the last recorded tick
  long long trail = 0;
  long long size = 1024;
  bool no_labels = false;
};

}  // namespace

static int Snapshot(SnapshotArgs s) {
  std::string error;
#ifndef ESSAIM_HAVE_CAIRO
  std::fprintf(stderr, "essaim snapshot: this essaim was built without Cairo (install libcairo2-dev and rebuild)\n");
  return kExitBadInput;
#else
  std::string path = RecordingPathOf(s.run);
  if (!FileExists(path)) {
    std::fprintf(stderr, "essaim snapshot: no recording at %s: run the experiment with --record\n", path.c_str());
    return kExitBadInput;
  }
  Recording rec;
  if (!Recording::Read(path, &rec, &error)) {
    std::fprintf(stderr, "essaim snapshot: %s\n", error.c_str());
    return kExitBadInput;
  }
  uint64_t first = rec.Tick(0), last = rec.Tick(rec.FrameCount() - 1);
  uint64_t tick = s.tick < 0 ? last : static_cast<uint64_t>(s.tick);
  if (tick < first || tick > last) {
    std::fprintf(stderr, "essaim snapshot: tick %llu was not recorded: %s holds ticks %llu to %llu\n",
                 static_cast<unsigned long long>(tick), path.c_str(), static_cast<unsigned long long>(first),
                 static_cast<unsigned long long>(last));
    return kExitBadInput;
  }
  size_t frame = rec.FrameAtOrBefore(tick);
  uint64_t shown = rec.Tick(frame);
  if (s.out.empty())
    s.out = JoinPath(path == s.run ? DirName(s.run) : s.run, "snapshot-" + std::to_string(shown) + ".png");
  if (!CheckOutputFile(s.out, &error)) {  // before drawing: a wrong target is bad input
    std::fprintf(stderr, "essaim snapshot: %s\n", error.c_str());
    return kExitBadInput;
  }
  SnapshotOptions opt;
  opt.size = static_cast<int>(s.size);
  opt.trail_ticks = static_cast<int>(std::min<long long>(s.trail, 0x7FFFFFFF));
  opt.labels = !s.no_labels;
  std::string png;
  if (!RenderSnapshotPng(rec, frame, opt, &png, &error) || !WriteFileAtomic(s.out, png, &error)) {
    std::fprintf(stderr, "essaim snapshot: %s\n", error.c_str());
    return kExitRunFailed;
  }
  if (shown != tick)
    std::fprintf(stderr, "essaim snapshot: tick %llu was not recorded (every %u ticks); drew tick %llu\n",
                 static_cast<unsigned long long>(tick), rec.scene().every, static_cast<unsigned long long>(shown));
  std::printf("%s\n", s.out.c_str());
  return kExitOk;
#endif
}

CommandMain AddSnapshotCommand(CLI::App& app) {
  auto s = std::make_shared<SnapshotArgs>();
  CLI::App* sub = app.add_subcommand("snapshot", "draw one recorded tick as a PNG");
  sub->add_option("RUN_DIR", s->run, "a run folder (or its recording.bin), from essaim run --record")->required();
  sub->add_option("-t,--tick", s->tick, "the tick to draw, >= 0 (default: the last recorded)")
      ->type_name("T")
      ->check(IntegerIn(0, 0xFFFFFFFFll));
  sub->add_option("-o,--out", s->out, "the PNG to write (default RUN_DIR/snapshot-<tick>.png)")->type_name("FILE.png");
  sub->add_option("--trail", s->trail, "also draw each robot's path over the N ticks before")
      ->type_name("N")
      ->check(IntegerIn(0, 0xFFFFFFFFll))
      ->capture_default_str();
  sub->add_option("--size", s->size, "image width and height in pixels, 16 to 8192")
      ->type_name("PX")
      ->check(IntegerIn(16, 8192))
      ->capture_default_str();
  sub->add_flag("--no-labels", s->no_labels, "leave out the tick (top left) and the robots' ids");
  sub->footer(
      "Example: (runs/foraging-7 is the recording made by the example of essaim run --help)\n"
      "  essaim snapshot runs/foraging-7 --tick 500 --trail 100 -o tick500.png");
  return [s] { return Snapshot(*s); };
}

}  // namespace essaim
