#include "output/recording_writer.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

#include "core/paths.h"
#include "model/floor_image.h"
#include "output/atomic_file.h"
#include "sim/world.h"

namespace essaim {

namespace {

// ---- floor ------------------------------------------------------------------------

/// The raster downsampled (nearest pixel) to at most kRecordingFloorMaxSide per side, as a
/// PNG whose top row is the arena's max y.
bool EncodeFloor(const FloorRaster& f, std::string* png, int* out_w, int* out_h) {
  png->clear();
  *out_w = *out_h = 0;
  if (f.Empty() || f.width <= 0 || f.height <= 0) return true;
  double scale = std::min(1.0, static_cast<double>(kRecordingFloorMaxSide) / std::max(f.width, f.height));
  int w = std::max(1, static_cast<int>(std::lround(f.width * scale)));
  int h = std::max(1, static_cast<int>(std::lround(f.height * scale)));
  std::vector<uint8_t> rgb(static_cast<size_t>(w) * h * 3);
  for (int row = 0; row < h; ++row) {
    int sy = std::min(f.height - 1, static_cast<int>((h - 1 - row + 0.5) * f.height / h));  // raster: bottom first
    for (int col = 0; col < w; ++col) {
      int sx = std::min(f.width - 1, static_cast<int>((col + 0.5) * f.width / w));
      const Color& c = f.pixels[static_cast<size_t>(sy) * f.width + sx];
      uint8_t* d = &rgb[(static_cast<size_t>(row) * w + col) * 3];
      d[0] = c.r;
      d[1] = c.g;
      d[2] = c.b;
    }
  }
  if (!EncodePngRgb(rgb, w, h, png)) return false;
  *out_w = w;
  *out_h = h;
  return true;
}

}  // namespace

Color RepresentativeColor(const Color* leds, int n) {
  for (int i = 0; i < n; ++i)
    if (!leds[i].IsBlack()) return leds[i];
  return Color{0, 0, 0, 255};
}

Color ObstacleLed(const ObstacleDef& o) {
  for (const LedDef& l : o.leds)
    if (!l.color.IsBlack()) return l.color;
  return Color{0, 0, 0, 255};
}

namespace {
RecordedObstacle RecordedOf(const ObstacleDef& o) {
  RecordedObstacle ro;
  ro.id = o.id;
  ro.cylinder = o.kind == ShapeKind::Cylinder;
  ro.movable = o.movable;
  ro.pose = o.pose;
  ro.size_x = o.size_x;
  ro.size_y = o.size_y;
  ro.radius = o.radius;
  ro.height = o.height;
  ro.led = ObstacleLed(o);
  return ro;
}

void PutMovable(uint8_t* p, const World& w, const EntityRef& ref, const Vec2& center, double unit) {
  const int k = w.entities.IndexOf(ref);
  if (k < 0) {  // removed by the loop functions (or not added yet)
    Put16(p + 0, static_cast<uint16_t>(kRecGone));
    Put16(p + 2, 0);
    Put16(p + 4, 0);
    Put16(p + 6, 0);
    return;
  }
  Pose2 pose = w.physics.ObstaclePose(k);
  Put16(p + 0, static_cast<uint16_t>(QuantisePosition(pose.x, center.x(), unit)));
  Put16(p + 2, static_cast<uint16_t>(QuantisePosition(pose.y, center.y(), unit)));
  Put16(p + 4, QuantiseYaw(pose.yaw));
  Put16(p + 6, PackRgb565(ObstacleLed(w.model.obstacles[k])));  // loop functions may recolour it
}

void PutRobot(uint8_t* p, const World& w, int i, const Vec2& center, double unit) {
  const RobotState& r = w.robots[i];
  Pose2 pose = w.physics.RobotPose(i);
  Put16(p + 0, static_cast<uint16_t>(QuantisePosition(pose.x, center.x(), unit)));
  Put16(p + 2, static_cast<uint16_t>(QuantisePosition(pose.y, center.y(), unit)));
  Put16(p + 4, QuantiseYaw(pose.yaw));
  Put16(p + 6, PackRgb565(RepresentativeColor(r.leds, footbot::kLedCount)));
  double full = w.model.robots[i].battery.full_charge;
  double frac = full > 0 ? r.battery.charge / full : 0;
  if (!std::isfinite(frac)) frac = 0;
  p[8] = static_cast<uint8_t>(std::lround(std::clamp(frac, 0.0, 1.0) * 255));
  p[9] = static_cast<uint8_t>((r.alive ? kRecAlive : 0) | (r.controller_ok ? kRecControllerOk : 0));
}

// The slot of a robot or obstacle in the frames before it was added: x = kRecGone, the
// rest zero (so a robot's flags say dead too, for readers that only look at those).
template <size_t N>
struct AbsentSlot {
  uint8_t bytes[N] = {};
  AbsentSlot() { Put16(bytes, static_cast<uint16_t>(kRecGone)); }
};
}  // namespace

RecordingScene SceneOf(const World& w, uint32_t every) {
  const Model& m = w.model;
  RecordingScene s;
  s.experiment = m.file;
  s.seed = m.experiment.seed;
  s.ticks_per_second = static_cast<uint32_t>(m.experiment.ticks_per_second);
  s.length_ticks = static_cast<uint32_t>(std::min<uint64_t>(m.experiment.length_ticks, UINT32_MAX));
  s.every = std::max<uint32_t>(1, every);
  s.arena_min = m.arena.Min();
  s.arena_size = Vec2(m.arena.size.x(), m.arena.size.y());
  // int16 around the arena centre, covering 1.5 times the arena: 1 mm up to 43 m arenas.
  s.position_unit = std::max(0.001, std::max(s.arena_size.x(), s.arena_size.y()) * 0.75 / 32767.0);
  s.robot_radius = footbot::kRadius;
  for (const RobotDef& r : m.robots) s.robot_ids.push_back(r.id);
  for (size_t i = 0; i < m.obstacles.size(); ++i) {
    s.obstacles.push_back(RecordedOf(m.obstacles[i]));
    if (m.obstacles[i].movable) s.movable.push_back(static_cast<int>(i));
  }
  for (const LightDef& l : m.lights) s.lights.push_back({l.id, l.position, l.color, l.intensity});
  EncodeFloor(w.floor, &s.floor_png, &s.floor_width, &s.floor_height);
  return s;
}

// ---- writer -----------------------------------------------------------------------

RecordingWriter::~RecordingWriter() {
  if (file_) {
    Close();
    std::remove(tmp_.c_str());
  }
}

void RecordingWriter::Close() {
  if (file_) std::fclose(file_);
  file_ = nullptr;
}

void RecordingWriter::Fail(int err) {
  failure_ = "cannot write " + path_ + ": " + std::strerror(err ? err : EIO);
  Close();
  std::remove(tmp_.c_str());
}

bool RecordingWriter::Open(const std::string& path, const World& world, uint32_t every, std::string* error) {
  path_ = path;
  tmp_ = path + ".tmp." + std::to_string(::getpid());
  scene_ = SceneOf(world, every);
  movable_refs_.clear();
  for (int k : scene_.movable) movable_refs_.push_back(world.entities.ObstacleRef(k));
  added_seen_ = world.entities.Added().size();  // those added in init() are in the scene
  late_robots_.Clear(), late_movables_.Clear();
  late_robot_ids_.clear(), late_obstacles_.clear(), late_lights_.clear();
  uint32_t frame_bytes = kFrameTickBytes + kRecordedRobotBytes * static_cast<uint32_t>(scene_.robot_ids.size()) +
                         kRecordedMovableBytes * static_cast<uint32_t>(scene_.movable.size());
  frame_.assign(frame_bytes, 0);
  file_ = std::fopen(tmp_.c_str(), "wb");
  if (!file_) {
    *error = "cannot write " + tmp_ + ": " + std::strerror(errno);
    return false;
  }
  // A buffer of many frames: the step loop only copies bytes into it.
  io_buffer_.resize(std::max<size_t>(1 << 20, 4 * static_cast<size_t>(frame_bytes)));
  std::setvbuf(file_, io_buffer_.data(), _IOFBF, io_buffer_.size());
  std::string header = SerializeScene(scene_, frame_bytes);
  errno = 0;
  if (std::fwrite(header.data(), 1, header.size(), file_) != header.size()) Fail(errno);
  header_bytes_ = header.size();
  if (file_) WriteFrame(world);
  if (!failure_.empty()) {
    *error = failure_;
    return false;
  }
  return true;
}

void RecordingWriter::Record(const World& world) {
  if (file_ && world.tick % scene_.every == 0 && world.tick != last_tick_) WriteFrame(world);
}

void RecordingWriter::WriteFrame(const World& w) {
  uint8_t* p = frame_.data();
  Put32(p, static_cast<uint32_t>(std::min<uint64_t>(w.tick, UINT32_MAX)));
  p += kFrameTickBytes;
  const Vec2 center = scene_.arena_min + scene_.arena_size / 2;
  const double unit = scene_.position_unit;
  const size_t n = scene_.robot_ids.size();
  for (size_t i = 0; i < n; ++i, p += kRecordedRobotBytes) PutRobot(p, w, static_cast<int>(i), center, unit);
  for (const EntityRef& ref : movable_refs_) {
    PutMovable(p, w, ref, center, unit);
    p += kRecordedMovableBytes;
  }
  RecordLate(w, center, unit);
  errno = 0;
  if (std::fwrite(frame_.data(), 1, frame_.size(), file_) != frame_.size()) return Fail(errno);
  ++frames_;
  last_tick_ = w.tick;
}

bool RecordingWriter::Finish(const World& world, std::string* error) {
  if (file_ && world.tick != last_tick_) WriteFrame(world);
  return Seal(error);
}

bool RecordingWriter::Seal(std::string* error) {
  if (!file_) {
    *error = failure_.empty() ? "recording " + path_ + " is not open" : failure_;
    return false;
  }
  // The first failure's errno is the reason (fclose after a failed flush may set another).
  int err = 0;
  errno = 0;
  if (std::fflush(file_) != 0 || ::fsync(fileno(file_)) != 0) err = errno ? errno : EIO;
  if (std::fclose(file_) != 0 && !err) err = errno ? errno : EIO;
  file_ = nullptr;
  if (!err && (!late_robot_ids_.empty() || !late_obstacles_.empty() || !late_lights_.empty())) {
    std::string rewrite_error;
    if (!RewriteWithLate(&rewrite_error)) {
      failure_ = rewrite_error;
      *error = failure_;
      std::remove(tmp_.c_str());
      return false;
    }
  }
  if (!err && std::rename(tmp_.c_str(), path_.c_str()) != 0) err = errno;
  if (err) {
    failure_ = "cannot write " + path_ + ": " + std::strerror(err);
    *error = failure_;
    std::remove(tmp_.c_str());
    return false;
  }
  return true;
}

uint8_t* RecordingWriter::LateSlots::NextFrame(size_t slot_bytes) {
  const size_t at = bytes.size();
  bytes.resize(at + slot_bytes * refs.size());
  frame_end.push_back(bytes.size());
  return bytes.data() + at;
}

void RecordingWriter::LateSlots::AppendFrame(uint64_t f, const uint8_t* absent, size_t slot_bytes, size_t* cursor,
                                             std::string* out) const {
  size_t have = 0;
  if (first_frame <= f && f - first_frame < frame_end.size()) {
    const size_t end = frame_end[f - first_frame];
    out->append(reinterpret_cast<const char*>(bytes.data()) + *cursor, end - *cursor);
    have = (end - *cursor) / slot_bytes;
    *cursor = end;
  }
  for (size_t j = have; j < refs.size(); ++j) out->append(reinterpret_cast<const char*>(absent), slot_bytes);
}

void RecordingWriter::NoteAdded(const World& w, const EntityRef& ref, int index) {
  if (ref.kind == EntityKind::Light) {
    const LightDef& l = w.model.lights[index];
    late_lights_.push_back({l.id, l.position, l.color, l.intensity});
    return;
  }
  const bool robot = ref.kind == EntityKind::FootBot;
  LateSlots& late = robot ? late_robots_ : late_movables_;
  if (late.refs.empty()) late.first_frame = frames_;
  late.refs.push_back(ref);
  if (robot)
    late_robot_ids_.push_back(w.model.robots[index].id);
  else
    late_obstacles_.push_back(RecordedOf(w.model.obstacles[index]));
}

void RecordingWriter::RecordLate(const World& w, const Vec2& center, double unit) {
  const std::vector<EntityRef>& added = w.entities.Added();
  for (; added_seen_ < added.size(); ++added_seen_) {
    const EntityRef& ref = added[added_seen_];
    const int k = w.entities.IndexOf(ref);
    if (k >= 0) NoteAdded(w, ref, k);  // else added and removed between two frames: never seen
  }
  // The usual case, nothing added: nothing kept, nothing allocated.
  if (!late_robots_.refs.empty()) {
    uint8_t* p = late_robots_.NextFrame(kRecordedRobotBytes);
    for (const EntityRef& ref : late_robots_.refs) {
      PutRobot(p, w, w.entities.IndexOf(ref), center, unit);  // robots are never removed
      p += kRecordedRobotBytes;
    }
  }
  if (!late_movables_.refs.empty()) {
    uint8_t* p = late_movables_.NextFrame(kRecordedMovableBytes);
    for (const EntityRef& ref : late_movables_.refs) {
      PutMovable(p, w, ref, center, unit);
      p += kRecordedMovableBytes;
    }
  }
}

namespace {
/// The scene with what was added after Open appended: robots to the ids, boxes and
/// cylinders to the obstacles and the movable list, lights to the lights.
RecordingScene SceneWithLate(RecordingScene s, const std::vector<std::string>& robot_ids,
                             const std::vector<RecordedObstacle>& obstacles, const std::vector<RecordedLight>& lights) {
  s.robot_ids.insert(s.robot_ids.end(), robot_ids.begin(), robot_ids.end());
  for (const RecordedObstacle& o : obstacles) {
    s.movable.push_back(static_cast<int>(s.obstacles.size()));
    s.obstacles.push_back(o);
  }
  s.lights.insert(s.lights.end(), lights.begin(), lights.end());
  return s;
}
}  // namespace

bool RecordingWriter::RewriteWithLate(std::string* error) {
  // Entities added after the first frame widen every frame by their slots: the whole file
  // is rewritten once, at the end, with them marked absent in the frames before their arrival.
  std::string old;
  if (!ReadFile(tmp_, &old) || old.size() < header_bytes_ + frames_ * frame_.size()) {
    *error = "cannot read back " + tmp_;
    return false;
  }
  const size_t width = frame_.size(), robots_end = kFrameTickBytes + kRecordedRobotBytes * scene_.robot_ids.size();
  const size_t wide =
      width + kRecordedRobotBytes * late_robots_.refs.size() + kRecordedMovableBytes * late_movables_.refs.size();
  std::string out = SerializeScene(SceneWithLate(scene_, late_robot_ids_, late_obstacles_, late_lights_),
                                   static_cast<uint32_t>(wide));
  out.reserve(out.size() + frames_ * wide);
  const AbsentSlot<kRecordedRobotBytes> absent_robot;
  const AbsentSlot<kRecordedMovableBytes> absent_movable;
  size_t robot_cursor = 0, movable_cursor = 0;
  for (uint64_t f = 0; f < frames_; ++f) {  // tick, robots, late robots, movables, late movables
    const size_t at = header_bytes_ + f * width;
    out.append(old, at, robots_end);
    late_robots_.AppendFrame(f, absent_robot.bytes, kRecordedRobotBytes, &robot_cursor, &out);
    out.append(old, at + robots_end, width - robots_end);
    late_movables_.AppendFrame(f, absent_movable.bytes, kRecordedMovableBytes, &movable_cursor, &out);
  }
  std::string err;
  if (!WriteFileAtomic(tmp_, out, &err)) {
    *error = "cannot write " + path_ + ": " + err;
    return false;
  }
  return true;
}

}  // namespace essaim
