// The one place essaim runs FFmpeg (Debian's `ffmpeg` program): raw frames piped into its
// stdin, encoded into a video file (`essaim video`, docs/video.md). A child process rather
// than FFmpeg's libraries: nothing to link, and the codecs are the ones the user's ffmpeg has.
#pragma once
#include <sys/types.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace essaim {

/// The containers `essaim video` writes, chosen by the output's extension.
enum class VideoFormat { Mp4, Webm, Gif };

/// The format of `path` by its extension (.mp4, .webm, .gif, any case); false for others.
bool VideoFormatOf(const std::string& path, VideoFormat* format);

struct VideoStreamSpec {
  int width = 0, height = 0;  // px (even for mp4 and webm: their 4:2:0 chroma needs it)
  int fps = 25;
  VideoFormat format = VideoFormat::Mp4;
  /// How the frames' bytes are laid out, as ffmpeg's -pix_fmt names it ("bgr0": Cairo's
  /// RGB24 on little-endian machines).
  std::string pixel_format = "bgr0";
};

/// An ffmpeg process encoding the frames written to it into `path`.
class FfmpegPipe {
 public:
  FfmpegPipe() = default;
  ~FfmpegPipe();  // an unfinished encoder is stopped and waited for
  FfmpegPipe(const FfmpegPipe&) = delete;
  FfmpegPipe& operator=(const FfmpegPipe&) = delete;

  /// Starts `ffmpeg` (found on PATH). False with why: not installed (the message names the
  /// Debian package), or it could not be started.
  bool Start(const VideoStreamSpec& spec, const std::string& path, std::string* error);
  /// Writes one frame: `height` rows of `width` * 4 bytes, each row `stride` bytes after the
  /// one before. False once ffmpeg has stopped reading (it failed: Finish says why).
  bool WriteFrame(const uint8_t* pixels, int stride);
  /// Ends the stream and waits for ffmpeg; false with its last error lines when it failed.
  bool Finish(std::string* error);

  /// The arguments ffmpeg is run with (for the docs and the tests).
  static std::vector<std::string> Arguments(const VideoStreamSpec& spec, const std::string& path);

 private:
  bool WriteAll(const uint8_t* data, size_t n);
  std::string ErrorOutput();
  VideoStreamSpec spec_;
  pid_t pid_ = -1;
  int stdin_fd_ = -1;
  int stderr_fd_ = -1;  // a temporary file holding what ffmpeg printed
};

}  // namespace essaim
