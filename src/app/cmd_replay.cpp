// `essaim replay RUN_DIR`: the run's recording in one self-contained HTML page
// (docs/replay.md). The page is src/app/replay_template.html, embedded at build time; the
// recording goes in as base64 and is decoded by the page itself.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>

#include "app/commands.h"
#include "app/web_pages.h"
#include "core/paths.h"
#include "core/strings.h"
#include "output/atomic_file.h"
#include "output/recording.h"

namespace essaim {

namespace {

bool IsDirectory(const std::string& path) {
  std::error_code ec;
  return std::filesystem::is_directory(path, ec);
}

}  // namespace

std::string RecordingPathOf(const std::string& run) { return IsDirectory(run) ? JoinPath(run, kRecordingFile) : run; }

/// The page with the recording embedded, and the run's time series when the recording's
/// folder has one (charts).
static std::string ReplayHtml(const Recording& rec, const std::string& recording_path) {
  std::string csv;
  std::ifstream in(JoinPath(DirName(recording_path), "timeseries.csv"), std::ios::binary);
  if (in) csv.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return ReplayPage(Base64Encode(rec.bytes()), csv);
}

static int Replay(const std::string& run, std::string out) {
  std::string path = RecordingPathOf(run), error;
  if (!FileExists(path)) {
    std::fprintf(stderr, "essaim replay: no recording at %s: run the experiment with --record\n", path.c_str());
    return kExitBadInput;
  }
  Recording rec;
  if (!Recording::Read(path, &rec, &error)) {
    std::fprintf(stderr, "essaim replay: %s\n", error.c_str());
    return kExitBadInput;
  }
  if (out.empty()) out = JoinPath(IsDirectory(run) ? run : DirName(run), "replay.html");
  if (!CheckOutputFile(out, &error)) {  // before building the page: a wrong target is bad input
    std::fprintf(stderr, "essaim replay: %s\n", error.c_str());
    return kExitBadInput;
  }
  if (!WriteFileAtomic(out, ReplayHtml(rec, path), &error)) {
    std::fprintf(stderr, "essaim replay: %s\n", error.c_str());
    return kExitRunFailed;
  }
  std::printf("%s\n", out.c_str());
  return kExitOk;
}

CommandMain AddReplayCommand(CLI::App& app) {
  struct Args {
    std::string run, out;
  };
  auto a = std::make_shared<Args>();
  CLI::App* sub = app.add_subcommand("replay", "write a self-contained replay page (HTML) of a recorded run");
  sub->add_option("RUN_DIR", a->run, "a run folder (or its recording.bin), from essaim run --record")->required();
  sub->add_option("-o,--out", a->out, "the page to write (default RUN_DIR/replay.html)")->type_name("FILE.html");
  sub->footer("Example:\n  essaim run arenas/foraging.argos --ticks 300 --record --out runs/f && essaim replay runs/f");
  return [a] { return Replay(a->run, a->out); };
}

}  // namespace essaim
