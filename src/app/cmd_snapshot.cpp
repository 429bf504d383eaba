// `essaim snapshot RUN_DIR --tick T -o FILE.png [--trail N] [--size PX]`: one frame of a
// recorded run as a PNG (docs/replay.md), drawn by app/render_cairo.cpp.
#include <algorithm>
#include <cstdio>

#include "app/commands.h"
#include "core/strings.h"
#include "output/atomic_file.h"
#include "output/recording.h"
#ifdef ESSAIM_HAVE_CAIRO
#include "app/render_cairo.h"
#endif

namespace essaim {

namespace {

struct SnapshotArgs {
  std::string run, out;
  long long tick = -1;  // -1: the last recorded tick
  long long trail = 0;
  long long size = 1024;
};

bool ParseSnapshotArgs(const std::vector<std::string>& args, SnapshotArgs* s, std::string* error) {
  for (size_t i = 0; i < args.size(); ++i) {
    std::string a = args[i], v;
    size_t eq = a.find('=');
    bool inline_value = a.rfind("--", 0) == 0 && eq != std::string::npos;
    if (inline_value) {
      v = a.substr(eq + 1);
      a = a.substr(0, eq);
    }
    auto value = [&]() {
      if (inline_value) return true;
      if (i + 1 >= args.size()) {
        *error = a + " needs a value";
        return false;
      }
      v = args[++i];
      return true;
    };
    auto integer = [&](long long* out, long long min, long long max) {
      if (!value()) return false;
      auto n = ParseInt(v);
      if (!n || *n < min || *n > max) {
        *error = a + ": '" + v + "' must be an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
        return false;
      }
      *out = *n;
      return true;
    };
    if (a == "--tick" || a == "-t") {
      if (!integer(&s->tick, 0, 0xFFFFFFFFll)) return false;
    } else if (a == "--trail") {
      if (!integer(&s->trail, 0, 0xFFFFFFFFll)) return false;
    } else if (a == "--size") {
      if (!integer(&s->size, 16, 8192)) return false;
    } else if (a == "-o" || a == "--out") {
      if (!value()) return false;
      s->out = v;
    } else if (!a.empty() && a[0] == '-') {
      *error = "unknown option " + a;
      return false;
    } else if (s->run.empty()) {
      s->run = a;
    } else {
      *error = "unexpected argument " + a;
      return false;
    }
  }
  if (s->run.empty()) {
    *error = "missing the run folder (usage: essaim snapshot RUN_DIR --tick T -o FILE.png [--trail N] [--size PX])";
    return false;
  }
  return true;
}

}  // namespace

int SnapshotCommand(const std::vector<std::string>& args) {
  SnapshotArgs s;
  std::string error;
  if (!ParseSnapshotArgs(args, &s, &error)) {
    std::fprintf(stderr, "essaim snapshot: %s\n", error.c_str());
    return kExitBadInput;
  }
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
  if (s.out.empty()) s.out = JoinPath(path == s.run ? DirName(s.run) : s.run, "snapshot-" + std::to_string(shown) + ".png");
  SnapshotOptions opt;
  opt.size = static_cast<int>(s.size);
  opt.trail_ticks = static_cast<int>(std::min<long long>(s.trail, 0x7FFFFFFF));
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

}  // namespace essaim
