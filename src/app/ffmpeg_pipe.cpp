#include "app/ffmpeg_pipe.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>

extern char** environ;

namespace essaim {

bool VideoFormatOf(const std::string& path, VideoFormat* format) {
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return false;
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "mp4")
    *format = VideoFormat::Mp4;
  else if (ext == "webm")
    *format = VideoFormat::Webm;
  else if (ext == "gif")
    *format = VideoFormat::Gif;
  else
    return false;
  return true;
}

namespace {
/// Each container's codec: H.264 in MP4 and VP9 in WebM (4:2:0, what players and browsers
/// take), both at their fast settings; GIF with a palette made for each frame (one made for
/// the whole video would hold every frame in ffmpeg's memory first).
std::vector<std::string> CodecArguments(VideoFormat format) {
  switch (format) {
    case VideoFormat::Mp4:
      return {"-c:v",     "libx264", "-preset",   "veryfast",   "-crf", "20",
              "-pix_fmt", "yuv420p", "-movflags", "+faststart", "-f",   "mp4"};
    case VideoFormat::Webm:
      return {"-c:v", "libvpx-vp9", "-deadline", "realtime", "-cpu-used", "8",       "-row-mt", "1",
              "-crf", "32",         "-b:v",      "0",        "-pix_fmt",  "yuv420p", "-f",      "webm"};
    case VideoFormat::Gif:
      return {"-vf", "split[a][b];[a]palettegen=stats_mode=single[p];[b][p]paletteuse=new=1", "-f", "gif"};
  }
  return {};
}
}  // namespace

std::vector<std::string> FfmpegPipe::Arguments(const VideoStreamSpec& spec, const std::string& path) {
  std::vector<std::string> args = {"ffmpeg",
                                   "-hide_banner",
                                   "-loglevel",
                                   "error",
                                   "-y",
                                   "-f",
                                   "rawvideo",
                                   "-pix_fmt",
                                   spec.pixel_format,
                                   "-video_size",
                                   std::to_string(spec.width) + "x" + std::to_string(spec.height),
                                   "-framerate",
                                   std::to_string(spec.fps),
                                   "-i",
                                   "pipe:0"};
  for (std::string& a : CodecArguments(spec.format)) args.push_back(std::move(a));
  args.push_back(path);
  return args;
}

FfmpegPipe::~FfmpegPipe() {
  if (stdin_fd_ >= 0) ::close(stdin_fd_);
  if (pid_ > 0) {
    ::kill(pid_, SIGTERM);
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
  }
  if (stderr_fd_ >= 0) ::close(stderr_fd_);
}

bool FfmpegPipe::Start(const VideoStreamSpec& spec, const std::string& path, std::string* error) {
  spec_ = spec;
  char name[] = "/tmp/essaim-ffmpeg-XXXXXX";
  stderr_fd_ = ::mkstemp(name);
  if (stderr_fd_ >= 0) ::unlink(name);
  int pipe_fds[2];
  if (stderr_fd_ < 0 || ::pipe2(pipe_fds, O_CLOEXEC) != 0) {
    *error = std::string("cannot start ffmpeg: ") + std::strerror(errno);
    return false;
  }
  // A write to an ffmpeg that died must fail with EPIPE, not end essaim.
  std::signal(SIGPIPE, SIG_IGN);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[0], 0);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, stderr_fd_, 2);
  std::vector<std::string> args = Arguments(spec, path);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const int err = posix_spawnp(&pid_, "ffmpeg", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(pipe_fds[0]);
  if (err != 0) {
    ::close(pipe_fds[1]);
    pid_ = -1;
    *error = err == ENOENT ? "ffmpeg not found on PATH: install Debian's ffmpeg package (sudo apt-get install ffmpeg)"
                           : std::string("cannot start ffmpeg: ") + std::strerror(err);
    return false;
  }
  stdin_fd_ = pipe_fds[1];
  return true;
}

bool FfmpegPipe::WriteAll(const uint8_t* data, size_t n) {
  while (n > 0) {
    ssize_t w = ::write(stdin_fd_, data, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    data += w;
    n -= static_cast<size_t>(w);
  }
  return true;
}

bool FfmpegPipe::WriteFrame(const uint8_t* pixels, int stride) {
  if (stdin_fd_ < 0) return false;
  const size_t row = static_cast<size_t>(spec_.width) * 4;
  if (static_cast<size_t>(stride) == row) return WriteAll(pixels, row * spec_.height);
  for (int y = 0; y < spec_.height; ++y)
    if (!WriteAll(pixels + static_cast<size_t>(y) * stride, row)) return false;
  return true;
}

std::string FfmpegPipe::ErrorOutput() {
  std::string text;
  char buf[4096];
  off_t at = 0;
  for (ssize_t n; (n = ::pread(stderr_fd_, buf, sizeof buf, at)) > 0; at += n) text.append(buf, n);
  if (text.size() > 2000) text = "..." + text.substr(text.size() - 2000);  // its last lines
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  return text;
}

bool FfmpegPipe::Finish(std::string* error) {
  if (pid_ <= 0) {
    *error = "ffmpeg is not running";
    return false;
  }
  ::close(stdin_fd_);
  stdin_fd_ = -1;
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return true;
  std::string out = ErrorOutput();
  *error = "ffmpeg failed (" +
           (WIFEXITED(status) ? "exit " + std::to_string(WEXITSTATUS(status))
                              : "signal " + std::to_string(WIFSIGNALED(status) ? WTERMSIG(status) : 0)) +
           ")" + (out.empty() ? "" : ":\n" + out);
  return false;
}

}  // namespace essaim
