// `essaim replay RUN_DIR`: the run's recording in one self-contained HTML page
// (docs/replay.md). The page is src/app/replay_template.html, embedded at build time; the
// recording goes in as base64 and is decoded by the page itself.
#include <sys/stat.h>

#include <cstdio>

#include "app/commands.h"
#include "core/strings.h"
#include "output/atomic_file.h"
#include "output/recording.h"

namespace essaim {

extern const char kReplayTemplate[];
extern const std::size_t kReplayTemplate_size;

namespace {

constexpr const char* kPlaceholder = "@ESSAIM_RECORDING@";

std::string Base64(const std::string& in) {
  static const char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  const auto* p = reinterpret_cast<const unsigned char*>(in.data());
  size_t i = 0;
  for (; i + 2 < in.size(); i += 3) {
    unsigned v = (p[i] << 16) | (p[i + 1] << 8) | p[i + 2];
    out += kAlphabet[v >> 18];
    out += kAlphabet[(v >> 12) & 63];
    out += kAlphabet[(v >> 6) & 63];
    out += kAlphabet[v & 63];
  }
  if (i < in.size()) {
    unsigned v = p[i] << 16;
    if (i + 1 < in.size()) v |= p[i + 1] << 8;
    out += kAlphabet[v >> 18];
    out += kAlphabet[(v >> 12) & 63];
    out += i + 1 < in.size() ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

bool IsDirectory(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

}  // namespace

std::string RecordingPathOf(const std::string& run) {
  return IsDirectory(run) ? JoinPath(run, kRecordingFile) : run;
}

/// The page with the recording embedded.
static std::string ReplayHtml(const Recording& rec) {
  std::string page(kReplayTemplate, kReplayTemplate_size);
  size_t at = page.find(kPlaceholder);
  if (at != std::string::npos) page.replace(at, std::char_traits<char>::length(kPlaceholder), Base64(rec.bytes()));
  return page;
}

int ReplayCommand(const std::vector<std::string>& args) {
  std::string run, out;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "-o" || a == "--out") {
      if (i + 1 >= args.size()) {
        std::fprintf(stderr, "essaim replay: %s needs a value\n", a.c_str());
        return kExitBadInput;
      }
      out = args[++i];
    } else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "essaim replay: unknown option %s\n", a.c_str());
      return kExitBadInput;
    } else if (run.empty()) {
      run = a;
    } else {
      std::fprintf(stderr, "essaim replay: unexpected argument %s\n", a.c_str());
      return kExitBadInput;
    }
  }
  if (run.empty()) {
    std::fprintf(stderr, "essaim replay: missing the run folder (usage: essaim replay RUN_DIR [-o FILE.html])\n");
    return kExitBadInput;
  }
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
  if (!WriteFileAtomic(out, ReplayHtml(rec), &error)) {
    std::fprintf(stderr, "essaim replay: %s\n", error.c_str());
    return kExitRunFailed;
  }
  std::printf("%s\n", out.c_str());
  return kExitOk;
}

}  // namespace essaim
