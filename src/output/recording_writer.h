// The recording's writer (docs/recording.md): streams a run's frames to a temporary file
// during the run and renames it when the run ends.
#pragma once
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "devices/entity_store.h"
#include "output/recording_format.h"

namespace essaim {

class World;

/// Streams a run into `path` (via path.tmp.PID). Record() after every Step; Finish() at
/// the end. The frame buffer and the stdio buffer are allocated by Open(): Record() does
/// not allocate, unless loop functions added foot-bots, boxes or cylinders during the run
/// (their slots are kept aside, and Finish() rewrites the file with them).
class RecordingWriter {
 public:
  RecordingWriter() = default;
  ~RecordingWriter();  // an unfinished recording's temporary file is removed
  RecordingWriter(const RecordingWriter&) = delete;
  RecordingWriter& operator=(const RecordingWriter&) = delete;

  /// Writes the scene and the frame of the world's current tick (usually 0).
  bool Open(const std::string& path, const World& world, uint32_t every, std::string* error);
  /// Writes a frame when the world's tick is a multiple of `every`. A failed write (a full
  /// disk) ends the recording at once: the temporary file is removed to free the space
  /// for the run's other outputs, and Failure() says why.
  void Record(const World& world);
  /// Writes the last tick's frame if it was not recorded, flushes and renames the file.
  /// False with the reason when any write failed, now or during the run.
  bool Finish(const World& world, std::string* error);
  /// Finish without a last frame: the frames written so far, flushed and renamed (the
  /// watchdog's last resort, while the world is mid-tick).
  bool Seal(std::string* error);
  bool IsOpen() const { return file_ != nullptr; }
  /// Why the recording stopped ("" while it goes on).
  const std::string& Failure() const { return failure_; }
  uint64_t FramesWritten() const { return frames_; }

 private:
  /// Frame slots of entities added after Open, one kind's: frames are fixed-size, so their
  /// slots wait here, frame after frame from the first arrival, until RewriteWithLate.
  struct LateSlots {
    std::vector<EntityRef> refs;  // in order of arrival, the order of their slots
    std::vector<uint8_t> bytes;
    std::vector<size_t> frame_end;  // end of each frame's slots in `bytes`
    uint64_t first_frame = 0;
    void Clear() { refs.clear(), bytes.clear(), frame_end.clear(); }
    /// Room for this frame's slots (`slot_bytes` each), to be filled by the caller.
    uint8_t* NextFrame(size_t slot_bytes);
    /// Frame `f`'s slots onto `out` from `*cursor` on, those not added yet as `absent`.
    void AppendFrame(uint64_t f, const uint8_t* absent, size_t slot_bytes, size_t* cursor, std::string* out) const;
  };
  void WriteFrame(const World& world);
  /// Slots of robots and obstacles added after Open (and lights added then), for RewriteWithLate.
  void RecordLate(const World& world, const Vec2& center, double unit);
  void NoteAdded(const World& world, const EntityRef& ref, int index);
  bool RewriteWithLate(std::string* error);
  void Close();
  void Fail(int err);
  std::string path_, tmp_, failure_;
  FILE* file_ = nullptr;
  std::vector<char> io_buffer_;
  std::vector<uint8_t> frame_;
  RecordingScene scene_;
  std::vector<EntityRef> movable_refs_;  // the recorded movable obstacles, found by ref as indices shift
  size_t header_bytes_ = 0;
  size_t added_seen_ = 0;                  // entries of EntityStore::Added() already looked at
  LateSlots late_robots_, late_movables_;  // foot-bots, boxes and cylinders added after Open
  std::vector<std::string> late_robot_ids_;
  std::vector<RecordedObstacle> late_obstacles_;
  std::vector<RecordedLight> late_lights_;
  uint64_t last_tick_ = UINT64_MAX;
  uint64_t frames_ = 0;
};

/// The scene of a World as the recorder stores it (floor downsampled, positions' unit
/// chosen from the arena size).
RecordingScene SceneOf(const World& world, uint32_t every);

/// The colour a robot or obstacle is drawn with (recordings, the live page): its first lit
/// LED; black when none is lit.
Color RepresentativeColor(const Color* leds, int n);
Color ObstacleLed(const ObstacleDef& o);

}  // namespace essaim
