// Ground sensors: base ground binary, motor ground grey, on a 4×2 test image
// with known, asymmetric pixels — bottom-left pixel at the arena's min corner, +X right,
// +Y up — the offsets rotating with the robot, noise, the Lua layout, init sees 0.
#include <gtest/gtest.h>
#include <png.h>

#include <cmath>
#include <cstring>

#include "devices/devices.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

// The picture as displayed, top row first (arena 4 m × 2 m centred at the origin, so
// each pixel is 1 m²):
//   top    (y in [0, 1]):  white  white  red    white
//   bottom (y in [-1, 0]): black  grey   white  white
const unsigned char kPixels[2][4][3] = {
    {{255, 255, 255}, {255, 255, 255}, {255, 0, 0}, {255, 255, 255}},
    {{0, 0, 0}, {128, 128, 128}, {255, 255, 255}, {255, 255, 255}},
};
constexpr double kRed = 0.299;  // grey level of (255, 0, 0)
constexpr double kGrey = 128 * (0.299 + 0.587 + 0.114) / 255;

void WriteTestPng(const std::string& path) {
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  image.width = 4;
  image.height = 2;
  image.format = PNG_FORMAT_RGB;
  ASSERT_TRUE(png_image_write_to_file(&image, path.c_str(), 0, kPixels, 0, nullptr)) << image.message;
}

std::string Xml(const std::string& robots, const std::string& sensors) {
  return "<argos-configuration>\n"
         "  <framework><experiment length=\"1\" ticks_per_second=\"10\" random_seed=\"5\"/></framework>\n"
         "  <controllers><lua_controller id=\"c\"><actuators><differential_steering implementation=\"default\"/>"
         "</actuators><sensors>" +
         sensors +
         "</sensors><params script=\"c.lua\"/></lua_controller></controllers>\n"
         "  <arena size=\"4,2,1\" center=\"0,0,0.5\"><floor id=\"floor\" source=\"image\" path=\"floor.png\"/>" +
         robots +
         "</arena>\n"
         "  <physics_engines><dynamics2d id=\"dyn2d\"/></physics_engines>\n"
         "  <media/>\n"
         "</argos-configuration>\n";
}

const char* kBoth =
    "<footbot_base_ground implementation=\"rot_z_only\" noise_level=\"0\"/>"
    "<footbot_motor_ground implementation=\"rot_z_only\"/>";

Scene RunScene(const TempDir& d, const std::string& robots, const std::string& sensors = kBoth,
               const std::string& lua = "function init() end function step() end") {
  WriteTestPng(d.path() + "/floor.png");
  d.Write("c.lua", lua);
  Scene s = Load(d, Xml(robots, sensors));
  if (s.ok()) RunTicks(*s.world, 1);
  return s;
}

TEST(Ground, ImageOrientationBottomLeftIsArenaMinCorner) {
  TempDir d;
  Scene s = RunScene(d, FootBot("a", -1.5, -0.5, 0, "c") + FootBot("b", 0.5, 0.5, 0, "c") +
                            FootBot("c", -0.5, -0.5, 0, "c") + FootBot("d", 1.5, 0.5, 0, "c"));
  ASSERT_TRUE(s.ok()) << s.error;
  auto motor = [&](int r) { return s.world->robots[r].rd.motor_ground; };
  auto base = [&](int r) { return s.world->robots[r].rd.base_ground; };
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(motor(0)[i], 0.0) << "bottom-left pixel is black";
    EXPECT_NEAR(motor(1)[i], kRed, 1e-12) << "top row, third pixel is red";
    EXPECT_NEAR(motor(2)[i], kGrey, 1e-12) << "bottom row, second pixel is grey";
    EXPECT_NEAR(motor(3)[i], 1.0, 1e-12) << "top-right pixel is white";
  }
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(base(0)[i], 0.0);
    EXPECT_EQ(base(1)[i], 0.0);  // 0.299 < 0.5
    EXPECT_EQ(base(2)[i], 1.0);  // 0.502 ≥ 0.5
    EXPECT_EQ(base(3)[i], 1.0);
  }
}

// Found by fuzz_argos (UBSan): a robot 1e48 m from a far-off arena overflowed the
// double-to-int cast of its floor cell. Anything outside reads the nearest edge.
TEST(Ground, FarOrNonFinitePointsReadAnEdgePixel) {
  FloorRaster f;
  f.width = 2;
  f.height = 1;
  f.pixels = {Color{0, 0, 0, 255}, Color{255, 0, 0, 255}};
  f.min = Vec2(-1, -1);
  f.size = Vec2(2, 2);
  EXPECT_EQ(f.At(-0.5, 0).r, 0);
  EXPECT_EQ(f.At(0.5, 0).r, 255);
  EXPECT_EQ(f.At(-8.9e48, 0).r, 0);
  EXPECT_EQ(f.At(8.9e48, -8.9e48).r, 255);
  EXPECT_EQ(f.At(std::nan(""), std::nan("")).r, 0);
  EXPECT_EQ(f.At(1e300, 1e300).r, 255);
}

TEST(Ground, OffsetsTurnWithTheRobot) {
  // Straddling the black|grey border at x = −1: 5 cm into the grey pixel.
  TempDir d2;
  Scene t = RunScene(d2, FootBot("a", -0.95, -0.5, 0, "c"));
  ASSERT_TRUE(t.ok()) << t.error;
  const double* b = t.world->robots[0].rd.base_ground;
  const double* m = t.world->robots[0].rd.motor_ground;
  // Base: front (+8 cm) at x = −0.87 grey → 1; back (−8 cm) at x = −1.03 black → 0;
  // left/right (x = −0.95) grey → 1; front-left/right (+4.2) grey; back ones (−4.2) at
  // x = −0.992 still grey.
  const double expect_base[8] = {1, 1, 1, 1, 0, 1, 1, 1};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(b[i], expect_base[i]) << "base " << i + 1;
  // Motor: front ones (x = −0.887) grey, back ones (x = −1.013) black.
  EXPECT_NEAR(m[0], kGrey, 1e-12);
  EXPECT_EQ(m[1], 0.0);
  EXPECT_EQ(m[2], 0.0);
  EXPECT_NEAR(m[3], kGrey, 1e-12);
  // Turned around (yaw 180°) at x = −1.05: the front now points to −X, into black.
  TempDir d3;
  Scene u = RunScene(d3, FootBot("a", -1.05, -0.5, 180, "c"));
  ASSERT_TRUE(u.ok()) << u.error;
  const double* ub = u.world->robots[0].rd.base_ground;
  const double* um = u.world->robots[0].rd.motor_ground;
  EXPECT_EQ(ub[0], 0.0);             // front at x = −1.13
  EXPECT_EQ(ub[4], 1.0);             // back at x = −0.97, grey
  EXPECT_EQ(um[0], 0.0);             // front-left at x = −1.113
  EXPECT_NEAR(um[1], kGrey, 1e-12);  // back-left at x = −0.987
}

TEST(Ground, LeftSensorsLookLeft) {
  TempDir d;
  // At y = −0.05 facing +X: the left sensors (+Y) reach into the top row (y ≥ 0), the
  // right ones stay in the bottom row. Column x in [0, 1): top red, bottom white.
  Scene s = RunScene(d, FootBot("a", 0.5, -0.05, 0, "c"));
  ASSERT_TRUE(s.ok()) << s.error;
  const double* b = s.world->robots[0].rd.base_ground;
  // Left (y +8 cm) and front-left/back-left (y +6.5 cm) on red → 0; the rest on white.
  const double expect_base[8] = {1, 0, 0, 0, 1, 1, 1, 1};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(b[i], expect_base[i]) << "base " << i + 1;
  // Motor sensors at y ± 1.16 cm stay in the white bottom row.
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(s.world->robots[0].rd.motor_ground[i], 1.0, 1e-12);
}

TEST(Ground, NoiseKeepsBaseBinaryAndMotorClamped) {
  TempDir d;
  Scene s = RunScene(d, FootBot("a", -0.5, -0.5, 0, "c"),
                     "<footbot_base_ground implementation=\"rot_z_only\" noise_level=\"0.3\"/>"
                     "<footbot_motor_ground implementation=\"rot_z_only\" noise_level=\"0.3\"/>");
  ASSERT_TRUE(s.ok()) << s.error;
  int ones = 0, zeros = 0;
  bool motor_varies = false;
  for (int t = 0; t < 30; ++t) {
    RunTicks(*s.world, 1);
    for (double v : s.world->robots[0].rd.base_ground) {
      EXPECT_TRUE(v == 0.0 || v == 1.0) << v;
      ones += v == 1.0;
      zeros += v == 0.0;
    }
    for (double v : s.world->robots[0].rd.motor_ground) {
      EXPECT_GE(v, 0.0);
      EXPECT_LE(v, 1.0);
      EXPECT_LE(std::fabs(v - kGrey), 0.3 + 1e-12);
      motor_varies |= std::fabs(v - kGrey) > 1e-3;
    }
  }
  // On grey (0.502) the noise flips the binary reading about half the time.
  EXPECT_GT(ones, 50);
  EXPECT_GT(zeros, 50);
  EXPECT_TRUE(motor_varies);
}

TEST(Ground, LuaValueOffsetTablesAndInitSeesZero) {
  TempDir d;
  Scene s = RunScene(d, FootBot("a", 1.5, 0.5, 0, "c"), kBoth, R"(
function init()
  assert(#robot.base_ground == 8 and #robot.motor_ground == 4)
  for i = 1, 8 do assert(robot.base_ground[i].value == 0, "init sees 0") end
  for i = 1, 4 do assert(robot.motor_ground[i].value == 0) end
  local o = robot.base_ground[2].offset
  assert(o.x == 4.2 and o.y == 6.5, tostring(o))
  assert(robot.base_ground[7].offset.y == -8)
  local m = robot.motor_ground[3].offset
  assert(m.x == -6.3 and m.y == -1.16)
  keep = robot.motor_ground[1]
end
function step()
  assert(robot.motor_ground[1] == keep)
  assert(math.abs(keep.value - 1) < 1e-12 and robot.base_ground[5].value == 1)
end
)");
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 1);
  ASSERT_TRUE(s.world->controller_errors.empty()) << s.world->controller_errors[0].message;
}

TEST(Ground, LoopFunctionFloor) {
  TempDir d;
  d.Write("c.lua", "function init() end function step() end");
  // Black left half, white right half.
  d.Write("loop.lua", "function floor_color(x, y) if x < 0 then return 0, 0, 0 end return 255, 255, 255 end");
  std::string xml = Xml(FootBot("a", -0.5, 0, 0, "c") + FootBot("b", 0.5, 0, 0, "c"), kBoth);
  const std::string image = "<floor id=\"floor\" source=\"image\" path=\"floor.png\"/>";
  xml.replace(xml.find(image), image.size(), "<floor id=\"floor\" source=\"loop_functions\" pixels_per_meter=\"10\"/>");
  xml.replace(xml.find("  <media/>"), 0, "  <loop_functions script=\"loop.lua\"/>\n");
  Scene s = Load(d, xml);
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 1);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(s.world->robots[0].rd.motor_ground[i], 0.0);
    EXPECT_NEAR(s.world->robots[1].rd.motor_ground[i], 1.0, 1e-12);
  }
}

}  // namespace
}  // namespace essaim

namespace essaim {
namespace {
using namespace essaim::testing;

TEST(RaySensors, RefreshingTheLuaTablesAllocatesNothing) {
  // Every sensor of this family on, the scanner switching between its modes; step()
  // itself allocates nothing. After the warm-up the Lua state must not allocate at all.
  TempDir d;
  WriteTestPng(d.path() + "/floor.png");
  d.Write("c.lua", R"(
local ds = robot.distance_scanner
n = 0
total = 0
function init() ds.set_rpm(100) end
function step()
  n = n + 1
  local s = 0
  for i = 1, 24 do s = s + robot.proximity[i].value + robot.light[i].value end
  for i = 1, 8 do s = s + robot.base_ground[i].value end
  for i = 1, 4 do s = s + robot.motor_ground[i].value end
  for i = 1, #ds.short_range do s = s + ds.short_range[i].distance end
  for i = 1, #ds.long_range do s = s + ds.long_range[i].angle end
  total = total + s
  local phase = n % 30
  if phase == 10 then ds.set_angle(1) elseif phase == 20 then ds.disable() elseif phase == 0 then ds.set_rpm(100) end
end
)");
  std::string sensors = std::string(kBoth) +
                        "<footbot_proximity implementation=\"default\"/><footbot_light implementation=\"rot_z_only\"/>"
                        "<footbot_distance_scanner implementation=\"rot_z_only\"/>";
  std::string xml = Xml(FootBot("a", 0.5, 0.5, 0, "c") + FootBot("b", 0.75, 0.5, 0, "c") +
                            "<light id=\"l\" position=\"1,0,0.3\" orientation=\"0,0,0\" color=\"yellow\" "
                            "intensity=\"1\" medium=\"leds\"/>",
                        sensors);
  xml.replace(xml.find("</actuators>"), 0, "<footbot_distance_scanner implementation=\"default\"/>");
  Scene s = Load(d, xml);
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 60);
  ASSERT_TRUE(s.world->controller_errors.empty()) << s.world->controller_errors[0].message;
  const size_t before = s.world->controllers[0]->Memory().allocations;
  RunTicks(*s.world, 90);
  EXPECT_EQ(s.world->controllers[0]->Memory().allocations, before);
  EXPECT_GT(s.world->robots[0].rd.proximity[0], 0);  // the other robot is in view
}

}  // namespace
}  // namespace essaim
