#include "output/recording.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

#include "core/paths.h"
#include "core/strings.h"
#include "model/floor_image.h"
#include "output/atomic_file.h"
#include "sim/world.h"

namespace essaim {

namespace {

constexpr char kMagic[8] = {'E', 'S', 'S', 'A', 'I', 'M', 'R', 'C'};

// ---- little-endian encoding -------------------------------------------------------

void Put16(uint8_t* p, uint16_t v) {
  p[0] = static_cast<uint8_t>(v);
  p[1] = static_cast<uint8_t>(v >> 8);
}
void Put32(uint8_t* p, uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = static_cast<uint8_t>(v >> (8 * i));
}
uint16_t Get16(const uint8_t* p) { return static_cast<uint16_t>(p[0] | (p[1] << 8)); }
uint32_t Get32(const uint8_t* p) {
  return static_cast<uint32_t>(p[0]) | (static_cast<uint32_t>(p[1]) << 8) | (static_cast<uint32_t>(p[2]) << 16) |
         (static_cast<uint32_t>(p[3]) << 24);
}

/// Appends values to a growing byte string (the header only; frames use a fixed buffer).
struct ByteSink {
  std::string out;
  void U8(uint8_t v) { out.push_back(static_cast<char>(v)); }
  void U16(uint16_t v) {
    uint8_t b[2];
    Put16(b, v);
    out.append(reinterpret_cast<char*>(b), 2);
  }
  void U32(uint32_t v) {
    uint8_t b[4];
    Put32(b, v);
    out.append(reinterpret_cast<char*>(b), 4);
  }
  void U64(uint64_t v) {
    U32(static_cast<uint32_t>(v));
    U32(static_cast<uint32_t>(v >> 32));
  }
  void F32(double v) {
    float f = static_cast<float>(v);
    uint32_t u;
    std::memcpy(&u, &f, 4);
    U32(u);
  }
  void F64(double v) {
    uint64_t u;
    std::memcpy(&u, &v, 8);
    U64(u);
  }
  void Str(const std::string& s) {
    size_t n = std::min<size_t>(s.size(), 65535);
    U16(static_cast<uint16_t>(n));
    out.append(s, 0, n);
  }
};

/// Reads values with bounds checks; `ok` turns false at the first overrun.
struct ByteSource {
  const uint8_t* p;
  size_t size, pos = 0;
  bool ok = true;
  const uint8_t* Take(size_t n) {
    if (!ok || pos + n > size) {
      ok = false;
      return nullptr;
    }
    const uint8_t* r = p + pos;
    pos += n;
    return r;
  }
  uint8_t U8() {
    const uint8_t* b = Take(1);
    return b ? b[0] : 0;
  }
  uint16_t U16() {
    const uint8_t* b = Take(2);
    return b ? Get16(b) : 0;
  }
  uint32_t U32() {
    const uint8_t* b = Take(4);
    return b ? Get32(b) : 0;
  }
  uint64_t U64() {
    uint64_t lo = U32();
    return lo | (static_cast<uint64_t>(U32()) << 32);
  }
  double F32() {
    uint32_t u = U32();
    float f;
    std::memcpy(&f, &u, 4);
    return f;
  }
  double F64() {
    uint64_t u = U64();
    double d;
    std::memcpy(&d, &u, 8);
    return d;
  }
  std::string Str() {
    uint16_t n = U16();
    const uint8_t* b = Take(n);
    return b ? std::string(reinterpret_cast<const char*>(b), n) : std::string();
  }
};

// ---- quantisation -----------------------------------------------------------------

int16_t QuantisePosition(double v, double center, double unit) {
  double q = std::round((v - center) / unit);
  if (!(q == q)) q = 0;  // NaN
  return static_cast<int16_t>(std::clamp(q, -32767.0, 32767.0));
}
uint16_t QuantiseYaw(double yaw) {
  if (!std::isfinite(yaw)) return 0;
  double q = std::round(WrapUnsigned(yaw) * (65536.0 / kTwoPi));
  return static_cast<uint16_t>(static_cast<uint32_t>(q) & 0xFFFF);
}
double YawOf(uint16_t q) { return q * (kTwoPi / 65536.0); }

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

std::string SerializeScene(const RecordingScene& s, uint32_t frame_bytes) {
  ByteSink b;
  b.out.append(kMagic, 8);
  b.U32(kRecordingVersion);
  b.U32(0);  // header bytes, patched below
  b.U32(frame_bytes);
  b.U32(s.every);
  b.U32(s.ticks_per_second);
  b.U32(s.length_ticks);
  b.U32(static_cast<uint32_t>(s.robot_ids.size()));
  b.U32(static_cast<uint32_t>(s.obstacles.size()));
  b.U32(static_cast<uint32_t>(s.movable.size()));
  b.U32(static_cast<uint32_t>(s.lights.size()));
  b.U64(s.seed);
  b.F64(s.arena_min.x());
  b.F64(s.arena_min.y());
  b.F64(s.arena_size.x());
  b.F64(s.arena_size.y());
  b.F64(s.position_unit);
  b.F64(s.robot_radius);
  // 104 bytes so far: the fixed part of the header
  b.Str(s.experiment);
  for (const std::string& id : s.robot_ids) b.Str(id);
  for (const RecordedObstacle& o : s.obstacles) {
    b.U8(o.cylinder ? 1 : 0);
    b.U8(o.movable ? 1 : 0);
    b.F32(o.pose.x);
    b.F32(o.pose.y);
    b.F32(o.pose.yaw);
    b.F32(o.size_x);
    b.F32(o.size_y);
    b.F32(o.radius);
    b.F32(o.height);
    b.U16(PackRgb565(o.led));
    b.Str(o.id);
  }
  for (int k : s.movable) b.U32(static_cast<uint32_t>(k));
  for (const RecordedLight& l : s.lights) {
    b.F32(l.position.x());
    b.F32(l.position.y());
    b.F32(l.position.z());
    b.U8(l.color.r);
    b.U8(l.color.g);
    b.U8(l.color.b);
    b.U8(l.color.a);
    b.F32(l.intensity);
    b.Str(l.id);
  }
  b.U16(static_cast<uint16_t>(s.floor_width));
  b.U16(static_cast<uint16_t>(s.floor_height));
  b.U32(static_cast<uint32_t>(s.floor_png.size()));
  b.out += s.floor_png;
  while (b.out.size() % 4) b.U8(0);
  Put32(reinterpret_cast<uint8_t*>(&b.out[12]), static_cast<uint32_t>(b.out.size()));
  return b.out;
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

uint16_t PackRgb565(Color c) { return static_cast<uint16_t>(((c.r >> 3) << 11) | ((c.g >> 2) << 5) | (c.b >> 3)); }

Color UnpackRgb565(uint16_t v) {
  unsigned r = (v >> 11) & 31, g = (v >> 5) & 63, b = v & 31;
  Color c;
  c.r = static_cast<unsigned char>((r << 3) | (r >> 2));
  c.g = static_cast<unsigned char>((g << 2) | (g >> 4));
  c.b = static_cast<unsigned char>((b << 3) | (b >> 2));
  return c;
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

// ---- reader -----------------------------------------------------------------------

namespace {
// Every number a reader draws with must be finite and of a size a 2D arena can have:
// Cairo spins on NaN or astronomically large paths, and libpng/Cairo would try to allocate
// whatever a damaged floor header claims.
constexpr double kMaxCoordinate = 1e5;  // m
bool Bounded(double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; }

bool SaneScale(const RecordingScene& s) {
  return Bounded(s.arena_min.x(), -kMaxCoordinate, kMaxCoordinate) &&
         Bounded(s.arena_min.y(), -kMaxCoordinate, kMaxCoordinate) && Bounded(s.arena_size.x(), 1e-3, kMaxCoordinate) &&
         Bounded(s.arena_size.y(), 1e-3, kMaxCoordinate) && Bounded(s.position_unit, 1e-9, 1.0) &&
         Bounded(s.robot_radius, 0, 100) && s.every >= 1;
}

/// Width and height from a PNG's IHDR chunk (bytes 16..23), 0 when it is not a PNG.
void PngSize(const std::string& png, uint32_t* w, uint32_t* h) {
  static const unsigned char kSig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  *w = *h = 0;
  if (png.size() < 24 || std::memcmp(png.data(), kSig, 8) != 0 || png.compare(12, 4, "IHDR") != 0) return;
  const auto* b = reinterpret_cast<const uint8_t*>(png.data());
  *w = (uint32_t{b[16]} << 24) | (uint32_t{b[17]} << 16) | (uint32_t{b[18]} << 8) | b[19];
  *h = (uint32_t{b[20]} << 24) | (uint32_t{b[21]} << 16) | (uint32_t{b[22]} << 8) | b[23];
}

bool SaneGeometry(const RecordingScene& s) {
  for (const RecordedObstacle& o : s.obstacles)
    if (!Bounded(o.pose.x, -kMaxCoordinate, kMaxCoordinate) || !Bounded(o.pose.y, -kMaxCoordinate, kMaxCoordinate) ||
        !Bounded(o.pose.yaw, -1e9, 1e9) || !Bounded(o.size_x, 0, kMaxCoordinate) ||
        !Bounded(o.size_y, 0, kMaxCoordinate) || !Bounded(o.radius, 0, kMaxCoordinate) ||
        !Bounded(o.height, 0, kMaxCoordinate))
      return false;
  for (const RecordedLight& l : s.lights)
    if (!Bounded(l.position.x(), -kMaxCoordinate, kMaxCoordinate) ||
        !Bounded(l.position.y(), -kMaxCoordinate, kMaxCoordinate) ||
        !Bounded(l.position.z(), -kMaxCoordinate, kMaxCoordinate) || !std::isfinite(l.intensity))
      return false;
  if (s.floor_png.empty()) return true;
  uint32_t w, h;
  PngSize(s.floor_png, &w, &h);
  return w >= 1 && h >= 1 && w <= kRecordingFloorMaxSide && h <= kRecordingFloorMaxSide;
}
}  // namespace

bool Recording::Read(const std::string& path, Recording* out, std::string* error) {
  std::string bytes;
  if (!ReadFile(path, &bytes)) {
    *error = "cannot read " + path;
    return false;
  }
  if (!Parse(std::move(bytes), out, error)) {
    *error = path + ": " + *error;
    return false;
  }
  return true;
}

namespace {
/// Entity counts in a recording's header.
struct SceneCounts {
  uint32_t robots = 0, obstacles = 0, movable = 0, lights = 0;
};

bool ReadPreamble(ByteSource& in, std::string* error) {
  const uint8_t* magic = in.Take(8);
  if (!magic || std::memcmp(magic, kMagic, 8) != 0) {
    *error = "not an essaim recording";
    return false;
  }
  uint32_t version = in.U32();
  if (version != kRecordingVersion) {
    *error = "recording version " + std::to_string(version) + " (this essaim reads version " +
             std::to_string(kRecordingVersion) + ")";
    return false;
  }
  return true;
}

/// The header's numbers after the two sizes: timing, counts, seed, arena, scale.
SceneCounts ReadSceneNumbers(ByteSource& in, RecordingScene* s) {
  s->every = in.U32();
  s->ticks_per_second = in.U32();
  s->length_ticks = in.U32();
  SceneCounts n;
  n.robots = in.U32();
  n.obstacles = in.U32();
  n.movable = in.U32();
  n.lights = in.U32();
  s->seed = in.U64();
  double mx = in.F64(), my = in.F64(), sx = in.F64(), sy = in.F64();
  s->arena_min = Vec2(mx, my);
  s->arena_size = Vec2(sx, sy);
  s->position_unit = in.F64();
  s->robot_radius = in.F64();
  return n;
}

RecordedObstacle ReadObstacle(ByteSource& in) {
  RecordedObstacle o;
  o.cylinder = in.U8() != 0;
  o.movable = in.U8() != 0;
  o.pose.x = in.F32();
  o.pose.y = in.F32();
  o.pose.yaw = in.F32();
  o.size_x = in.F32();
  o.size_y = in.F32();
  o.radius = in.F32();
  o.height = in.F32();
  o.led = UnpackRgb565(in.U16());
  o.id = in.Str();
  return o;
}

// The movable list names obstacles in increasing order: every one flagged movable, and
// those added during the run (static or not), whose poses the frames hold too.
void ReadMovableList(ByteSource& in, const SceneCounts& n, RecordingScene* s) {
  size_t flagged = 0, flagged_listed = 0;
  for (const RecordedObstacle& o : s->obstacles) flagged += o.movable ? 1 : 0;
  for (uint32_t i = 0; i < n.movable && in.ok; ++i) {
    uint32_t k = in.U32();
    if (k >= n.obstacles || (i > 0 && k <= static_cast<uint32_t>(s->movable.back()))) {
      in.ok = false;
      break;
    }
    flagged_listed += s->obstacles[k].movable ? 1 : 0;
    s->movable.push_back(static_cast<int>(k));
  }
  if (flagged_listed != flagged) in.ok = false;
}

RecordedLight ReadLight(ByteSource& in) {
  RecordedLight l;
  double x = in.F32(), y = in.F32(), z = in.F32();
  l.position = Vec3(x, y, z);
  l.color.r = in.U8();
  l.color.g = in.U8();
  l.color.b = in.U8();
  l.color.a = in.U8();
  l.intensity = in.F32();
  l.id = in.Str();
  return l;
}

/// The scene after the header's numbers: names, obstacles, the movable list, lights, floor.
/// Stops at the first short read (in.ok false).
void ReadSceneEntities(ByteSource& in, const SceneCounts& n, RecordingScene* s) {
  s->experiment = in.Str();
  for (uint32_t i = 0; i < n.robots && in.ok; ++i) s->robot_ids.push_back(in.Str());
  for (uint32_t i = 0; i < n.obstacles && in.ok; ++i) s->obstacles.push_back(ReadObstacle(in));
  ReadMovableList(in, n, s);
  for (uint32_t i = 0; i < n.lights && in.ok; ++i) s->lights.push_back(ReadLight(in));
  s->floor_width = in.U16();
  s->floor_height = in.U16();
  uint32_t png_bytes = in.U32();
  const uint8_t* png = in.Take(png_bytes);
  if (png) s->floor_png.assign(reinterpret_cast<const char*>(png), png_bytes);
}
}  // namespace

bool Recording::Parse(std::string bytes, Recording* out, std::string* error) {
  Recording r;
  r.bytes_ = std::move(bytes);
  ByteSource in{reinterpret_cast<const uint8_t*>(r.bytes_.data()), r.bytes_.size()};
  if (!ReadPreamble(in, error)) return false;
  RecordingScene& s = r.scene_;
  r.header_bytes_ = in.U32();
  r.frame_bytes_ = in.U32();
  const SceneCounts n = ReadSceneNumbers(in, &s);
  // In 64 bits: a damaged count must not wrap the product into a plausible frame size.
  const uint64_t frame_bytes = uint64_t{kFrameTickBytes} + uint64_t{kRecordedRobotBytes} * n.robots +
                               uint64_t{kRecordedMovableBytes} * n.movable;
  if (!in.ok || r.header_bytes_ > r.bytes_.size() || r.frame_bytes_ != frame_bytes || n.movable > n.obstacles ||
      !SaneScale(s)) {
    *error = "corrupt recording header";
    return false;
  }
  ReadSceneEntities(in, n, &s);
  if (!in.ok || in.pos > r.header_bytes_) {
    *error = "corrupt recording scene";
    return false;
  }
  if (!SaneGeometry(s)) {
    *error = "corrupt recording scene (non-finite or out-of-range geometry, or a bad floor image)";
    return false;
  }
  r.frame_count_ = (r.bytes_.size() - r.header_bytes_) / r.frame_bytes_;
  if (r.frame_count_ == 0) {
    *error = "recording has no frame";
    return false;
  }
  *out = std::move(r);
  return true;
}

uint64_t Recording::Tick(size_t frame) const {
  return Get32(reinterpret_cast<const uint8_t*>(bytes_.data()) + header_bytes_ + frame * frame_bytes_);
}

RecordedRobot Recording::Robot(size_t frame, size_t robot) const {
  const uint8_t* p = reinterpret_cast<const uint8_t*>(bytes_.data()) + header_bytes_ + frame * frame_bytes_ +
                     kFrameTickBytes + robot * kRecordedRobotBytes;
  const Vec2 center = scene_.arena_min + scene_.arena_size / 2;
  RecordedRobot r;
  if (static_cast<int16_t>(Get16(p)) == kRecGone) {  // not added yet
    r.battery = 0;
    r.alive = r.controller_ok = r.present = false;
    return r;
  }
  r.x = center.x() + static_cast<int16_t>(Get16(p)) * scene_.position_unit;
  r.y = center.y() + static_cast<int16_t>(Get16(p + 2)) * scene_.position_unit;
  r.yaw = YawOf(Get16(p + 4));
  r.color = UnpackRgb565(Get16(p + 6));
  r.battery = p[8] / 255.0;
  r.alive = (p[9] & kRecAlive) != 0;
  r.controller_ok = (p[9] & kRecControllerOk) != 0;
  return r;
}

Pose2 Recording::Movable(size_t frame, size_t k) const {
  const uint8_t* p = reinterpret_cast<const uint8_t*>(bytes_.data()) + header_bytes_ + frame * frame_bytes_ +
                     kFrameTickBytes + RobotCount() * kRecordedRobotBytes + k * kRecordedMovableBytes;
  const Vec2 center = scene_.arena_min + scene_.arena_size / 2;
  Pose2 pose;
  pose.x = center.x() + static_cast<int16_t>(Get16(p)) * scene_.position_unit;
  pose.y = center.y() + static_cast<int16_t>(Get16(p + 2)) * scene_.position_unit;
  pose.yaw = YawOf(Get16(p + 4));
  return pose;
}

Color Recording::MovableLed(size_t frame, size_t k) const {
  const uint8_t* p = reinterpret_cast<const uint8_t*>(bytes_.data()) + header_bytes_ + frame * frame_bytes_ +
                     kFrameTickBytes + RobotCount() * kRecordedRobotBytes + k * kRecordedMovableBytes;
  return UnpackRgb565(Get16(p + 6));
}

bool Recording::MovablePresent(size_t frame, size_t k) const {
  const uint8_t* p = reinterpret_cast<const uint8_t*>(bytes_.data()) + header_bytes_ + frame * frame_bytes_ +
                     kFrameTickBytes + RobotCount() * kRecordedRobotBytes + k * kRecordedMovableBytes;
  return static_cast<int16_t>(Get16(p)) != kRecGone;
}

size_t Recording::FrameAtOrBefore(uint64_t tick) const {
  size_t lo = 0, hi = frame_count_;  // first frame with Tick > tick, by bisection
  while (lo < hi) {
    size_t mid = (lo + hi) / 2;
    if (Tick(mid) <= tick)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo == 0 ? 0 : lo - 1;
}

}  // namespace essaim
