// `essaim video RUN_DIR -o FILE.mp4|.webm|.gif`: a recorded run drawn frame by frame with
// the snapshot renderer (render/render_cairo.cpp) and piped into ffmpeg (app/ffmpeg_pipe.cpp);
// docs/video.md. The recording is streamed: only its scene and the frames a trail reaches
// back over are held, whatever the recording's size.
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <memory>

#include "app/cli_support.h"
#include "app/commands.h"
#include "app/ffmpeg_pipe.h"
#include "app/signals.h"
#include "core/paths.h"
#include "core/stopwatch.h"
#include "core/strings.h"
#include "output/atomic_file.h"
#include "output/recording.h"
#ifdef ESSAIM_HAVE_CAIRO
#include "render/render_cairo.h"
#endif

namespace essaim {

namespace {
struct VideoArgs {
  std::string run, out, follow;
  long long fps = 25;
  long long from = -1, to = -1;  // -1: the first / last recorded tick
  long long every = 0;           // 0: the recording's
  long long size = 1024;
  long long trail = 0;
  double view = 0;  // m; 0: the whole arena, or kFollowView around a followed robot
  bool ids = false, no_labels = false;
};
}  // namespace

#ifdef ESSAIM_HAVE_CAIRO
namespace {

/// What the options and the recording decide together, checked before anything is drawn.
struct VideoPlan {
  std::string out;
  VideoFormat format = VideoFormat::Mp4;
  uint64_t from = 0, to = 0, every = 1, trail = 0;
  size_t frames = 0;      // video frames: the multiples of `every` in [from, to]
  size_t first_read = 0;  // the first recorded frame read (a trail reaches back before `from`)
  int width = 0, height = 0, fps = 25;
  int follow = -1;                // robot index, or -1
  Vec2 view_size = Vec2::Zero();  // m; zero: the whole arena
  DrawOptions draw;
};

constexpr double kFollowView = 3.0;  // m: the default view's width around a followed robot

std::string Text(uint64_t t) { return std::to_string(t); }

bool PlanTicks(const VideoArgs& a, const RecordingStream& rec, VideoPlan* p, std::string* error) {
  const uint64_t first = rec.TickOf(0), last = rec.TickOf(rec.FrameCount() - 1), every = rec.scene().every;
  p->from = a.from < 0 ? first : static_cast<uint64_t>(a.from);
  p->to = a.to < 0 ? last : std::min<uint64_t>(static_cast<uint64_t>(a.to), last);
  p->every = a.every > 0 ? static_cast<uint64_t>(a.every) : every;
  p->trail = static_cast<uint64_t>(a.trail);
  if (p->from > last) {
    *error = "--from " + Text(p->from) + " is after the recording's end: it holds ticks " + Text(first) + " to " +
             Text(last);
    return false;
  }
  if (a.to >= 0 && static_cast<uint64_t>(a.to) < p->from) {
    *error = "--to " + Text(a.to) + " is before --from " + Text(p->from);
    return false;
  }
  if (p->every % every != 0) {
    *error = "--every " + Text(p->every) + ": the recording has a frame every " + Text(every) +
             " ticks; use a multiple of " + Text(every);
    return false;
  }
  const uint64_t lo = (p->from + p->every - 1) / p->every, hi = p->to / p->every;
  if (hi < lo) {
    *error = "no tick from " + Text(p->from) + " to " + Text(p->to) + " is a multiple of --every " + Text(p->every);
    return false;
  }
  p->frames = static_cast<size_t>(hi - lo + 1);
  const uint64_t start = lo * p->every, back = std::min(start, p->trail);
  p->first_read = rec.FrameAtOrBefore(start - back);
  return true;
}

/// Width and height as a snapshot's, rounded up to even numbers (4:2:0 video needs them).
void VideoImageSize(const RecordingScene& scene, int size, int* width, int* height) {
  SnapshotImageSize(scene, size, width, height);
  *width += *width % 2;
  *height += *height % 2;
}

bool PlanView(const VideoArgs& a, const RecordingScene& scene, VideoPlan* p, std::string* error) {
  if (!a.follow.empty()) {
    const std::vector<std::string>& ids = scene.robot_ids;
    auto it = std::find(ids.begin(), ids.end(), a.follow);
    if (it == ids.end()) {
      std::string hint = ClosestName(a.follow, ids);
      *error = "--follow: no robot '" + a.follow + "' in the recording" +
               (hint.empty() ? "" : " (did you mean '" + hint + "'?)");
      return false;
    }
    p->follow = static_cast<int>(it - ids.begin());
  }
  VideoImageSize(scene, static_cast<int>(a.size), &p->width, &p->height);
  double width = a.view;
  if (width == 0 && p->follow >= 0) width = std::min(kFollowView, std::max(scene.arena_size.x(), scene.arena_size.y()));
  if (width > 0) p->view_size = Vec2(width, width * p->height / p->width);
  p->draw.tick = p->draw.scale_bar = !a.no_labels;
  p->draw.ids = a.ids;
  return true;
}

bool PlanOutput(const VideoArgs& a, const std::string& recording, VideoPlan* p, std::string* error) {
  p->out = a.out.empty() ? JoinPath(recording == a.run ? DirName(a.run) : a.run, "video.mp4") : a.out;
  if (!VideoFormatOf(p->out, &p->format)) {
    *error = "-o " + p->out + ": the name must end in .mp4, .webm or .gif (the format it is written in)";
    return false;
  }
  return CheckOutputFile(p->out, error);  // before drawing: a wrong target is bad input
}

/// The frames a trail is drawn through, oldest first, ending with the newest: frame buffers
/// are recycled, so the window costs its own frames' bytes and no allocation once full.
class FrameWindow {
 public:
  FrameWindow(const RecordingScene& scene, uint64_t trail) : scene_(scene), trail_(trail) {}
  /// A buffer for the next frame, to be filled and then passed to Push.
  std::vector<uint8_t> Take() {
    if (free_.empty()) return {};
    std::vector<uint8_t> b = std::move(free_.back());
    free_.pop_back();
    return b;
  }
  /// Adds the newest frame and drops those the trail no longer reaches (the trail starts at
  /// the last frame at or before `trail` ticks ago, as a snapshot's does).
  void Push(std::vector<uint8_t> bytes) {
    frames_.push_back(std::move(bytes));
    const uint64_t now = Get32(frames_.back().data()), from = now > trail_ ? now - trail_ : 0;
    while (frames_.size() >= 2 && (trail_ == 0 || Get32(frames_[1].data()) <= from)) {
      free_.push_back(std::move(frames_.front()));
      frames_.pop_front();
    }
  }
  const std::vector<FrameView>& Views() {
    views_.clear();
    for (const std::vector<uint8_t>& f : frames_) views_.emplace_back(&scene_, f.data());
    return views_;
  }

 private:
  const RecordingScene& scene_;
  uint64_t trail_;
  std::deque<std::vector<uint8_t>> frames_;
  std::vector<std::vector<uint8_t>> free_;
  std::vector<FrameView> views_;
};

/// A bar on a terminal: frames done, frames per second, time left (nothing when stderr is
/// not a terminal).
class VideoProgress {
 public:
  explicit VideoProgress(size_t total) : total_(total), enabled_(::isatty(2) != 0) {}
  void Update(size_t done) {
    const double now = SecondsSince(start_);
    if (!enabled_ || (now - last_ < 0.2 && done < total_)) return;
    last_ = now;
    const int width = 30, filled = static_cast<int>(width * done / std::max<size_t>(1, total_));
    const double rate = done / std::max(1e-9, now);
    std::fprintf(stderr, "\r  [%s%s] %3.0f%%  frame %zu/%zu  %.0f frames/s  ETA %.0fs   ",
                 std::string(filled, '#').c_str(), std::string(width - filled, '.').c_str(),
                 100.0 * done / std::max<size_t>(1, total_), done, total_, rate,
                 (total_ - done) / std::max(1e-9, rate));
    std::fflush(stderr);
  }
  void Finish() {
    if (enabled_) std::fprintf(stderr, "\r%*s\r", 100, "");
  }
  double Seconds() const { return SecondsSince(start_); }

 private:
  size_t total_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  double last_ = -1;
};

/// Where the view's min corner is for this frame: around the followed robot (where it was
/// last seen while it is absent), else around the arena's centre.
Vec2 ViewMin(const VideoPlan& p, const FrameView& frame, Vec2* centre) {
  if (p.follow >= 0) {
    RecordedRobot r = frame.Robot(static_cast<size_t>(p.follow));
    if (r.present) *centre = Vec2(r.x, r.y);
  }
  return *centre - p.view_size / 2;
}

/// Reads, draws and pipes every frame of the plan (`written` counts them). False with why (a
/// read or Cairo; ffmpeg says its own in Finish).
bool EncodeFrames(const VideoPlan& p, const RecordingStream& rec, const SignalCatcher& signals, FfmpegPipe* ffmpeg,
                  size_t* written, std::string* error) {
  const RecordingScene& scene = rec.scene();
  FrameRenderer renderer(scene, p.width, p.height);
  FrameWindow window(scene, p.trail);
  VideoProgress progress(p.frames);
  DrawOptions draw = p.draw;
  Vec2 centre = scene.arena_min + scene.arena_size / 2;
  draw.view_size = p.view_size;
  size_t& done = *written;
  for (size_t k = p.first_read; k < rec.FrameCount() && done < p.frames && !signals.Caught(); ++k) {
    std::vector<uint8_t> bytes = window.Take();
    if (!rec.ReadFrame(k, &bytes, error)) return false;
    const uint64_t tick = Get32(bytes.data());
    window.Push(std::move(bytes));
    if (tick < p.from || tick % p.every != 0) continue;
    const std::vector<FrameView>& views = window.Views();
    draw.view_min = ViewMin(p, views.back(), &centre);
    if (!renderer.Draw(views, draw, error)) return false;
    if (!ffmpeg->WriteFrame(renderer.Pixels(), renderer.Stride())) break;  // ffmpeg stopped: Finish says why
    progress.Update(++done);
  }
  progress.Finish();
  return true;
}

/// ffmpeg writes a temporary file beside the output, renamed once it succeeded: the video
/// is there whole or not at all.
int Encode(const VideoPlan& p, const RecordingStream& rec) {
  VideoStreamSpec spec;
  spec.width = p.width, spec.height = p.height, spec.fps = p.fps, spec.format = p.format;
#if __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
  spec.pixel_format = "0rgb";  // Cairo's RGB24 is native-endian 0x00RRGGBB
#endif
  std::string error, target;
  if (!ResolveOutput(p.out, &target, &error)) {  // a symlink is written through, as snapshots are
    std::fprintf(stderr, "essaim video: %s\n", error.c_str());
    return kExitBadInput;
  }
  const std::string tmp = target + ".tmp." + std::to_string(::getpid());
  FfmpegPipe ffmpeg;
  if (!ffmpeg.Start(spec, tmp, &error)) {
    std::fprintf(stderr, "essaim video: %s\n", error.c_str());
    return kExitBadInput;  // nothing was drawn: a missing program is like a missing input
  }
  const auto start = std::chrono::steady_clock::now();
  SignalCatcher signals(nullptr);
  signals.Listen();
  size_t frames = 0;  // p.frames, unless the recording lacks some of their ticks
  const bool drawn = EncodeFrames(p, rec, signals, &ffmpeg, &frames, &error);
  std::string ffmpeg_error;
  const bool encoded = ffmpeg.Finish(&ffmpeg_error);
  if (signals.Caught()) {  // Ctrl-C reaches ffmpeg too; either way no part of a video is left
    std::remove(tmp.c_str());
    std::fprintf(stderr, "\nessaim video: interrupted; %s not written\n", p.out.c_str());
    return 128 + signals.Caught();
  }
  if (!drawn || !encoded || std::rename(tmp.c_str(), target.c_str()) != 0) {
    std::remove(tmp.c_str());
    std::fprintf(stderr, "essaim video: %s\n",
                 (!drawn     ? error
                  : !encoded ? ffmpeg_error
                             : "cannot write " + p.out + ": " + std::strerror(errno))
                     .c_str());
    return kExitRunFailed;
  }
  const double seconds = SecondsSince(start);
  std::fprintf(stderr,
               "essaim video: %zu frames, %dx%d, %.2f s at %d fps (ticks %llu to %llu every %llu), drawn and "
               "encoded in %.1f s (%.0f frames/s)\n",
               frames, p.width, p.height, static_cast<double>(frames) / p.fps, p.fps,
               static_cast<unsigned long long>(p.from), static_cast<unsigned long long>(p.to),
               static_cast<unsigned long long>(p.every), seconds, frames / std::max(1e-9, seconds));
  std::printf("%s\n", p.out.c_str());
  return kExitOk;
}

}  // namespace

static int Video(const VideoArgs& a) {
  const std::string path = RecordingPathOf(a.run);
  if (!FileExists(path)) {
    std::fprintf(stderr, "essaim video: no recording at %s: run the experiment with --record\n", path.c_str());
    return kExitBadInput;
  }
  RecordingStream rec;
  VideoPlan plan;
  plan.fps = static_cast<int>(a.fps);
  std::string error;
  if (!rec.Open(path, &error) || !PlanTicks(a, rec, &plan, &error) || !PlanView(a, rec.scene(), &plan, &error) ||
      !PlanOutput(a, path, &plan, &error)) {
    std::fprintf(stderr, "essaim video: %s\n", error.c_str());
    return kExitBadInput;
  }
  return Encode(plan, rec);
}
#endif

CommandMain AddVideoCommand(CLI::App& app) {
  auto v = std::make_shared<VideoArgs>();
  CLI::App* sub = app.add_subcommand("video", "draw a recorded run as a video (.mp4, .webm or .gif) with ffmpeg");
  sub->add_option("RUN_DIR", v->run, "a run folder (or its recording.bin), from essaim run --record")->required();
  sub->add_option("-o,--out", v->out,
                  "the video to write: .mp4 (H.264), .webm (VP9) or .gif (default RUN_DIR/video.mp4)")
      ->type_name("FILE");
  sub->add_option("--fps", v->fps, "video frames per second, 1 to 240")
      ->type_name("N")
      ->check(IntegerIn(1, 240))
      ->capture_default_str();
  sub->add_option("--from", v->from, "the first tick shown (default: the first recorded)")
      ->type_name("T")
      ->check(IntegerIn(0, 0xFFFFFFFFll));
  sub->add_option("--to", v->to, "the last tick shown (default: the last recorded)")
      ->type_name("T")
      ->check(IntegerIn(0, 0xFFFFFFFFll));
  sub->add_option("--every", v->every, "a video frame every N ticks, a multiple of the recording's (default: its)")
      ->type_name("N")
      ->check(IntegerIn(1, 1000000));
  sub->add_option("--size", v->size, "the image's longer side in pixels, 16 to 8192 (rounded up to even)")
      ->type_name("PX")
      ->check(IntegerIn(16, 8192))
      ->capture_default_str();
  sub->add_option("--trail", v->trail, "draw each robot's path over the N ticks before")
      ->type_name("N")
      ->check(IntegerIn(0, 0xFFFFFFFFll))
      ->capture_default_str();
  sub->add_option("--follow", v->follow, "keep this robot (its id) at the centre of the view (3 m wide unless --view)")
      ->type_name("ROBOT");
  sub->add_option("--view", v->view,
                  "the view's width in metres, 0.01 to 100000 (default: the whole arena; 3 with --follow)")
      ->type_name("M")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            char* end = nullptr;
            const double m = std::strtod(text.c_str(), &end);
            if (end == text.c_str() || *end != '\0' || !(m >= 0.01 && m <= 1e5))
              return "'" + text + "' is not a width in metres from 0.01 to 100000";
            return "";
          },
          ""));
  sub->add_flag("--ids", v->ids, "draw each robot's id beside it");
  sub->add_flag("--no-labels", v->no_labels, "leave out the tick (top left) and the scale bar (bottom left)");
  sub->footer(
      "Example: (runs/foraging-7 is the recording made by the example of essaim run --help)\n"
      "  essaim video runs/foraging-7 -o foraging.mp4 --every 5 --trail 100");
  return [v] {
#ifdef ESSAIM_HAVE_CAIRO
    return Video(*v);
#else
    std::fprintf(stderr, "essaim video: this essaim was built without Cairo (install libcairo2-dev and rebuild)\n");
    return kExitBadInput;
#endif
  };
}

}  // namespace essaim
