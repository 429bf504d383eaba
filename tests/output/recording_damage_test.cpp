// Damaged recordings (issue: snapshot spun forever on damaged scene bytes): the reader
// refuses non-finite or absurd geometry, counts whose product wraps, and a floor image
// that claims more pixels than a recording ever holds, before anything draws with them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "core/strings.h"
#include "output/recording.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

const char* kPlain =
    "<lua_controller id=\"p\"><actuators><differential_steering implementation=\"default\"/></actuators>"
    "<sensors/><params script=\"" ESSAIM_SOURCE_DIR "/tests/support/idle.lua\"/></lua_controller>";

/// A recording of one robot beside a cylinder, as bytes.
std::string RecordedBytes(const TempDir& d) {
  std::string arena = FootBot("a", -1, -1, 0, "p") +
                      "<cylinder id=\"c\" radius=\"0.25\" height=\"0.5\" movable=\"false\">"
                      "<body position=\"1,1,0\" orientation=\"0,0,0\"/></cylinder>";
  Scene s = Load(d, Experiment(arena, kPlain, 5));
  EXPECT_TRUE(s.ok()) << s.error;
  if (!s.ok()) return "";
  const std::string path = d.path() + "/recording.bin";
  RecordingWriter w;
  std::string error;
  EXPECT_TRUE(w.Open(path, *s.world, 1, &error)) << error;
  for (int t = 0; t < 5; ++t) {
    Step(*s.world);
    w.Record(*s.world);
  }
  EXPECT_TRUE(w.Finish(*s.world, &error)) << error;
  std::string bytes;
  EXPECT_TRUE(ReadFile(path, &bytes));
  return bytes;
}

/// Offset of the first obstacle's record: after the fixed header, the experiment path and
/// the robot ids (docs/recording.md).
size_t FirstObstacleOffset(const std::string& b) {
  size_t pos = 104;
  auto str = [&] { pos += 2 + (static_cast<uint8_t>(b[pos]) | static_cast<uint8_t>(b[pos + 1]) << 8); };
  str();  // experiment
  str();  // one robot id
  return pos;
}

void PutF32(std::string* b, size_t at, float v) { std::memcpy(&(*b)[at], &v, 4); }

bool Parses(const std::string& bytes, std::string* error) {
  Recording r;
  return Recording::Parse(bytes, &r, error);
}

TEST(RecordingDamage, TheUndamagedFileParses) {
  TempDir d;
  std::string b = RecordedBytes(d), error;
  ASSERT_FALSE(b.empty());
  EXPECT_TRUE(Parses(b, &error)) << error;
}

TEST(RecordingDamage, NonFiniteOrHugeObstacleGeometryIsRefused) {
  TempDir d;
  const std::string good = RecordedBytes(d);
  ASSERT_FALSE(good.empty());
  const size_t o = FirstObstacleOffset(good);
  // cylinder flag, movable flag, then x, y, yaw, size_x, size_y, radius, height (f32)
  for (int field = 0; field < 7; ++field)
    for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(), 3e30f}) {
      if (field == 2 && std::isfinite(bad)) continue;  // any finite yaw is an angle
      std::string b = good, error;
      PutF32(&b, o + 2 + 4 * field, bad);
      EXPECT_FALSE(Parses(b, &error)) << "field " << field << " = " << bad;
      EXPECT_NE(error.find("corrupt"), std::string::npos) << error;
    }
}

// Found by fuzz_recording: an obstacle flagged movable that the movable list does not name
// made the snapshot read a pose past the end of the frame (heap overflow).
TEST(RecordingDamage, MovableFlagsMustMatchTheMovableList) {
  TempDir d;
  std::string b = RecordedBytes(d), error;
  ASSERT_FALSE(b.empty());
  b[FirstObstacleOffset(b) + 1] = 1;  // the fixed cylinder claims to be movable
  EXPECT_FALSE(Parses(b, &error));
  EXPECT_NE(error.find("corrupt"), std::string::npos) << error;
}

TEST(RecordingDamage, ArenaAndScaleMustBeFinite) {
  TempDir d;
  const std::string good = RecordedBytes(d);
  ASSERT_FALSE(good.empty());
  // arena min x, min y, size x, size y, position unit, robot radius: f64 at 56..103
  for (size_t at = 56; at < 104; at += 8)
    for (double bad : {std::nan(""), 1e300, -1.0}) {
      if (at < 72 && bad == -1.0) continue;  // a negative corner is fine
      std::string b = good, error;
      std::memcpy(&b[at], &bad, 8);
      EXPECT_FALSE(Parses(b, &error)) << "offset " << at << " = " << bad;
    }
}

TEST(RecordingDamage, CountsThatWrapTheFrameSizeAreRefused) {
  TempDir d;
  std::string b = RecordedBytes(d), error;
  ASSERT_FALSE(b.empty());
  // robots = 2^31 + 1: 10 × robots wraps to 10 in 32 bits, so a 32-bit check saw 1 robot.
  uint32_t robots = 0x80000001u;
  std::memcpy(&b[32], &robots, 4);
  EXPECT_FALSE(Parses(b, &error));
}
}  // namespace
}  // namespace essaim
