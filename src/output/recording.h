// Recorded runs (docs/recording.md): the static scene once, then one fixed-size frame of
// quantised robot and movable-obstacle state every N ticks. The writer streams frames to
// a temporary file during the run and renames it when the run ends; the reader gives
// random access to any frame (frames are fixed-size, so frame k sits at a computed offset).
#pragma once
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "core/math.h"
#include "devices/entity_store.h"

namespace essaim {

class World;

/// File name of a run's recording inside its output folder.
constexpr const char* kRecordingFile = "recording.bin";
constexpr uint32_t kRecordingVersion = 2;  // 2: LED colour of obstacles

/// Bytes of one recorded robot and one movable obstacle in a frame.
constexpr uint32_t kRecordedRobotBytes = 10;   // i16 x, i16 y, u16 yaw, u16 rgb565, u8 battery, u8 flags
constexpr uint32_t kRecordedMovableBytes = 8;  // i16 x, i16 y, u16 yaw, u16 rgb565
constexpr uint32_t kFrameTickBytes = 4;        // u32 tick

/// Flags of a recorded robot.
constexpr uint8_t kRecAlive = 1;         // not killed by the loop functions / battery
constexpr uint8_t kRecControllerOk = 2;  // no controller error so far

/// Quantised x of a movable obstacle removed during the run, or of a robot or obstacle in
/// the frames before the loop functions added it (never a quantised position).
constexpr int16_t kRecGone = INT16_MIN;

/// The floor raster is downsampled to at most this many pixels per side.
constexpr int kRecordingFloorMaxSide = 512;

struct RecordedObstacle {
  std::string id;
  bool cylinder = false;
  bool movable = false;
  Pose2 pose;                     // initial pose (m, rad); movable ones move per frame
  double size_x = 0, size_y = 0;  // box (m)
  double radius = 0;              // cylinder (m)
  double height = 0;              // m
  Color led;                      // its first lit LED at the start (RGB565 precision); black: none
};

struct RecordedLight {
  std::string id;
  Vec3 position = Vec3::Zero();  // m
  Color color;
  double intensity = 1;
};

/// What never changes during a run.
struct RecordingScene {
  std::string experiment;  // the .argos path as given to essaim run
  uint64_t seed = 0;
  uint32_t ticks_per_second = 10;
  uint32_t length_ticks = 0;       // planned length (0: unlimited)
  uint32_t every = 1;              // a frame every `every` ticks (plus the last tick)
  Vec2 arena_min = Vec2::Zero();   // m
  Vec2 arena_size = Vec2::Ones();  // m
  double position_unit = 0.001;    // m per quantisation step of a position
  double robot_radius = 0;         // m
  std::vector<std::string> robot_ids;
  std::vector<RecordedObstacle> obstacles;
  std::vector<int> movable;  // indices into obstacles that move, in frame order
  std::vector<RecordedLight> lights;
  /// Floor as PNG bytes (8-bit RGB, top row = arena max y, as any image); empty: none.
  std::string floor_png;
  int floor_width = 0, floor_height = 0;
};

/// One robot in one frame, dequantised.
struct RecordedRobot {
  double x = 0, y = 0, yaw = 0;  // m, m, rad in [0, 2pi)
  Color color;                   // first non-black LED (RGB565 precision); black: none lit
  double battery = 1;            // charge / full charge, 1/255 precision
  bool alive = true;
  bool controller_ok = true;
  /// False in the frames before the loop functions added it (its other fields are then
  /// zero, alive false): nothing to draw or count.
  bool present = true;
};

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
  uint64_t Tick(size_t frame) const;
  RecordedRobot Robot(size_t frame, size_t robot) const;
  Pose2 Movable(size_t frame, size_t k) const;  // pose of obstacles[scene.movable[k]]
  /// First lit LED of that movable obstacle in this frame (black: none).
  Color MovableLed(size_t frame, size_t k) const;
  /// False once the loop functions removed that movable obstacle (x written as kRecGone).
  bool MovablePresent(size_t frame, size_t k) const;
  /// The last frame whose tick is <= `tick` (0 if none is).
  size_t FrameAtOrBefore(uint64_t tick) const;

 private:
  RecordingScene scene_;
  std::string bytes_;
  size_t header_bytes_ = 0;
  uint32_t frame_bytes_ = 0;
  size_t frame_count_ = 0;
};

/// The scene of a World as the recorder stores it (floor downsampled, positions' unit
/// chosen from the arena size).
RecordingScene SceneOf(const World& world, uint32_t every);

/// RGB565 with bit replication on the way back (0 → 0, full → 255).
uint16_t PackRgb565(Color c);
Color UnpackRgb565(uint16_t v);
/// The colour a robot or obstacle is drawn with (recordings, the live page): its first lit
/// LED; black when none is lit.
Color RepresentativeColor(const Color* leds, int n);
Color ObstacleLed(const ObstacleDef& o);

}  // namespace essaim
