// The recording's readers (docs/recording.md): Recording holds a file whole and gives random
// access to its frames (replay, snapshot, Python); RecordingStream keeps only the scene and
// reads frames one at a time from the file, for recordings larger than memory (video).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "output/recording_format.h"

namespace essaim {

/// A recording read back whole into memory; frames are decoded on demand.
class Recording {
 public:
  /// Reads and validates a file. A trailing partial frame (a file cut short) is ignored.
  static bool Read(const std::string& path, Recording* out, std::string* error);
  static bool Parse(std::string bytes, Recording* out, std::string* error);

  const RecordingScene& scene() const { return scene_; }
  const std::string& bytes() const { return bytes_; }
  size_t RobotCount() const { return scene_.robot_ids.size(); }
  size_t FrameCount() const { return frame_count_; }
  uint32_t FrameBytes() const { return frame_bytes_; }
  /// Frame `frame` (< FrameCount()); valid while this Recording lives and is not moved.
  FrameView Frame(size_t frame) const {
    return FrameView(&scene_, reinterpret_cast<const uint8_t*>(bytes_.data()) + header_bytes_ + frame * frame_bytes_);
  }
  uint64_t Tick(size_t frame) const { return Frame(frame).Tick(); }
  RecordedRobot Robot(size_t frame, size_t robot) const { return Frame(frame).Robot(robot); }
  Pose2 Movable(size_t frame, size_t k) const { return Frame(frame).Movable(k); }
  Color MovableLed(size_t frame, size_t k) const { return Frame(frame).MovableLed(k); }
  bool MovablePresent(size_t frame, size_t k) const { return Frame(frame).MovablePresent(k); }
  /// The last frame whose tick is <= `tick` (0 if none is).
  size_t FrameAtOrBefore(uint64_t tick) const;

 private:
  RecordingScene scene_;
  std::string bytes_;
  size_t header_bytes_ = 0;
  uint32_t frame_bytes_ = 0;
  size_t frame_count_ = 0;
};

/// A recording read frame by frame: Open reads and checks the scene, ReadFrame reads one
/// frame's bytes from the file. Memory: the scene and what the caller keeps.
class RecordingStream {
 public:
  RecordingStream() = default;
  ~RecordingStream();
  RecordingStream(const RecordingStream&) = delete;
  RecordingStream& operator=(const RecordingStream&) = delete;

  /// Opens and validates a file; the frame count is taken from its size now (a trailing
  /// partial frame is ignored).
  bool Open(const std::string& path, std::string* error);
  const RecordingScene& scene() const { return header_.scene; }
  size_t FrameCount() const { return frame_count_; }
  uint32_t FrameBytes() const { return header_.frame_bytes; }
  /// Reads frame `frame` (< FrameCount()) into `bytes` (resized to FrameBytes()).
  bool ReadFrame(size_t frame, std::vector<uint8_t>* bytes, std::string* error) const;
  /// The tick of frame `frame`, read from the file (UINT64_MAX when it cannot be read).
  uint64_t TickOf(size_t frame) const;
  /// The last frame whose tick is <= `tick` (0 if none is), by bisection over the file.
  size_t FrameAtOrBefore(uint64_t tick) const;

 private:
  std::string path_;
  int fd_ = -1;
  RecordingHeader header_;
  size_t frame_count_ = 0;
};

}  // namespace essaim
