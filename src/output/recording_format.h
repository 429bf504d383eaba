// The recording format (docs/recording.md), shared by the writer, the readers and the Python
// module: constants, the scene and its header's encoding, quantisation, and a frame's bytes
// decoded on demand (FrameView). Nothing here knows the World.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"

namespace essaim {

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

/// RGB565 with bit replication on the way back (0 → 0, full → 255).
uint16_t PackRgb565(Color c);
Color UnpackRgb565(uint16_t v);

// ---- encoding -----------------------------------------------------------------------

inline void Put16(uint8_t* p, uint16_t v) {
  p[0] = static_cast<uint8_t>(v);
  p[1] = static_cast<uint8_t>(v >> 8);
}
inline void Put32(uint8_t* p, uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = static_cast<uint8_t>(v >> (8 * i));
}
inline uint16_t Get16(const uint8_t* p) { return static_cast<uint16_t>(p[0] | (p[1] << 8)); }
inline uint32_t Get32(const uint8_t* p) {
  return static_cast<uint32_t>(p[0]) | (static_cast<uint32_t>(p[1]) << 8) | (static_cast<uint32_t>(p[2]) << 16) |
         (static_cast<uint32_t>(p[3]) << 24);
}

/// Position relative to the arena centre in steps of `unit`, clamped to ±32767 (NaN: 0).
int16_t QuantisePosition(double v, double center, double unit);
/// Yaw in steps of 2π/65536 over [0, 2π).
uint16_t QuantiseYaw(double yaw);
double YawOf(uint16_t q);

/// Bytes at the start of every recording that say where frames start and how long they
/// are: magic, version, header bytes, frame bytes.
constexpr size_t kRecordingPreambleBytes = 20;

/// The header (scene) as written: frames start right after it (its size is a multiple of 4).
std::string SerializeScene(const RecordingScene& scene, uint32_t frame_bytes);

/// A recording's header, read back.
struct RecordingHeader {
  RecordingScene scene;
  size_t header_bytes = 0;   // frames start here
  uint32_t frame_bytes = 0;  // each frame's size
};

/// Reads and validates the header from the first `size` bytes of a recording (at least its
/// header bytes). False with why ("not an essaim recording", a version, "corrupt ...").
bool ParseRecordingHeader(const uint8_t* data, size_t size, RecordingHeader* out, std::string* error);
/// The header bytes a recording's preamble announces (0 when it is no recording's).
size_t HeaderBytesOf(const uint8_t* preamble, size_t size);

/// One frame's bytes decoded on demand. Holds pointers: the scene and the bytes must outlive it.
class FrameView {
 public:
  FrameView() = default;
  FrameView(const RecordingScene* scene, const uint8_t* bytes) : scene_(scene), p_(bytes) {}
  const RecordingScene& scene() const { return *scene_; }
  size_t RobotCount() const { return scene_->robot_ids.size(); }
  uint64_t Tick() const { return Get32(p_); }
  RecordedRobot Robot(size_t robot) const;
  Pose2 Movable(size_t k) const;  // pose of obstacles[scene.movable[k]]
  /// First lit LED of that movable obstacle in this frame (black: none).
  Color MovableLed(size_t k) const;
  /// False once the loop functions removed that movable obstacle (x written as kRecGone).
  bool MovablePresent(size_t k) const;

 private:
  const uint8_t* MovableBytes(size_t k) const;
  const RecordingScene* scene_ = nullptr;
  const uint8_t* p_ = nullptr;
};

/// The last of `frame_count` frames (ticks increasing) whose tick is at most `tick`, or 0:
/// `tick_of(k)` gives frame k's tick. Both readers' FrameAtOrBefore.
template <typename TickOf>
size_t LastFrameAtOrBefore(size_t frame_count, uint64_t tick, TickOf tick_of) {
  size_t lo = 0, hi = frame_count;  // first frame with a tick > tick, by bisection
  while (lo < hi) {
    const size_t mid = (lo + hi) / 2;
    if (tick_of(mid) <= tick)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo == 0 ? 0 : lo - 1;
}

}  // namespace essaim
