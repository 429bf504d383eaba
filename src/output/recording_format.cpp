#include "output/recording_format.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace essaim {

namespace {

constexpr char kMagic[8] = {'E', 'S', 'S', 'A', 'I', 'M', 'R', 'C'};

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

}  // namespace

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

uint16_t PackRgb565(Color c) { return static_cast<uint16_t>(((c.r >> 3) << 11) | ((c.g >> 2) << 5) | (c.b >> 3)); }

Color UnpackRgb565(uint16_t v) {
  unsigned r = (v >> 11) & 31, g = (v >> 5) & 63, b = v & 31;
  Color c;
  c.r = static_cast<unsigned char>((r << 3) | (r >> 2));
  c.g = static_cast<unsigned char>((g << 2) | (g >> 4));
  c.b = static_cast<unsigned char>((b << 3) | (b >> 2));
  return c;
}

// ---- the header -------------------------------------------------------------------

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

size_t HeaderBytesOf(const uint8_t* p, size_t size) {
  if (size < kRecordingPreambleBytes || std::memcmp(p, kMagic, 8) != 0) return 0;
  return Get32(p + 12);
}

bool ParseRecordingHeader(const uint8_t* data, size_t size, RecordingHeader* out, std::string* error) {
  ByteSource in{data, size};
  if (!ReadPreamble(in, error)) return false;
  RecordingHeader h;
  RecordingScene& s = h.scene;
  h.header_bytes = in.U32();
  h.frame_bytes = in.U32();
  const SceneCounts n = ReadSceneNumbers(in, &s);
  // In 64 bits: a damaged count must not wrap the product into a plausible frame size.
  const uint64_t frame_bytes = uint64_t{kFrameTickBytes} + uint64_t{kRecordedRobotBytes} * n.robots +
                               uint64_t{kRecordedMovableBytes} * n.movable;
  if (!in.ok || h.header_bytes > size || h.frame_bytes != frame_bytes || n.movable > n.obstacles || !SaneScale(s)) {
    *error = "corrupt recording header";
    return false;
  }
  ReadSceneEntities(in, n, &s);
  if (!in.ok || in.pos > h.header_bytes) {
    *error = "corrupt recording scene";
    return false;
  }
  if (!SaneGeometry(s)) {
    *error = "corrupt recording scene (non-finite or out-of-range geometry, or a bad floor image)";
    return false;
  }
  *out = std::move(h);
  return true;
}

// ---- frames -----------------------------------------------------------------------

RecordedRobot FrameView::Robot(size_t robot) const {
  const uint8_t* p = p_ + kFrameTickBytes + robot * kRecordedRobotBytes;
  const RecordingScene& s = *scene_;
  const Vec2 center = s.arena_min + s.arena_size / 2;
  RecordedRobot r;
  if (static_cast<int16_t>(Get16(p)) == kRecGone) {  // not added yet
    r.battery = 0;
    r.alive = r.controller_ok = r.present = false;
    return r;
  }
  r.x = center.x() + static_cast<int16_t>(Get16(p)) * s.position_unit;
  r.y = center.y() + static_cast<int16_t>(Get16(p + 2)) * s.position_unit;
  r.yaw = YawOf(Get16(p + 4));
  r.color = UnpackRgb565(Get16(p + 6));
  r.battery = p[8] / 255.0;
  r.alive = (p[9] & kRecAlive) != 0;
  r.controller_ok = (p[9] & kRecControllerOk) != 0;
  return r;
}

const uint8_t* FrameView::MovableBytes(size_t k) const {
  return p_ + kFrameTickBytes + RobotCount() * kRecordedRobotBytes + k * kRecordedMovableBytes;
}

Pose2 FrameView::Movable(size_t k) const {
  const uint8_t* p = MovableBytes(k);
  const Vec2 center = scene_->arena_min + scene_->arena_size / 2;
  Pose2 pose;
  pose.x = center.x() + static_cast<int16_t>(Get16(p)) * scene_->position_unit;
  pose.y = center.y() + static_cast<int16_t>(Get16(p + 2)) * scene_->position_unit;
  pose.yaw = YawOf(Get16(p + 4));
  return pose;
}

Color FrameView::MovableLed(size_t k) const { return UnpackRgb565(Get16(MovableBytes(k) + 6)); }

bool FrameView::MovablePresent(size_t k) const { return static_cast<int16_t>(Get16(MovableBytes(k))) != kRecGone; }

}  // namespace essaim
