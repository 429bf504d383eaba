// Proximity sensor: readings at hand-computed distances and angles to a wall
// and to another robot, the 0.06 m ray height, noise on every sensor, the Lua layout.
#include <gtest/gtest.h>

#include <cmath>

#include "devices/devices.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

constexpr double kR = footbot::kRadius;

std::string Controller(const std::string& script, const std::string& prox_attrs = "") {
  return "<lua_controller id=\"c\"><actuators><differential_steering implementation=\"default\"/></actuators>"
         "<sensors><footbot_proximity implementation=\"default\" show_rays=\"false\" " +
         prox_attrs + "/></sensors><params script=\"" + script + "\"/></lua_controller>";
}

/// Distance along the ray of sensor angle `a` (robot at the origin, yaw 0) to the plane x = X.
double ToPlaneX(double a, double X) { return X / std::cos(a) - kR; }

/// Distance along the ray of sensor angle `a` from the body surface of a robot at the
/// origin to a circle of radius `r` centred at (cx, cy); -1 if missed.
double ToCircle(double a, double cx, double cy, double r) {
  const double ux = std::cos(a), uy = std::sin(a);
  const double sx = kR * ux - cx, sy = kR * uy - cy;
  const double b = sx * ux + sy * uy;
  const double c = sx * sx + sy * sy - r * r;
  const double disc = b * b - c;
  if (disc < 0) return -1;
  return -b - std::sqrt(disc);
}

double Expected(double d) { return d < 0 || d > 0.1 ? 0.0 : (d < 0.009889556 ? 1.0 : 0.0100527 / (d + 0.000163144)); }

TEST(Proximity, ValueLaw) {
  EXPECT_DOUBLE_EQ(ProximityValue(0.05), 0.0100527 / (0.05 + 0.000163144));
  EXPECT_DOUBLE_EQ(ProximityValue(0.0), 1.0);
  EXPECT_DOUBLE_EQ(ProximityValue(0.009), 1.0);
  // Continuous at the saturation threshold, ≈ 0.1004 at the end of the range.
  EXPECT_NEAR(ProximityValue(0.009889556), 1.0, 1e-6);
  EXPECT_NEAR(ProximityValue(0.1), 0.10036, 1e-5);
}

TEST(Proximity, SensorAnglesAreCounterClockwiseFromFrontLeft) {
  EXPECT_NEAR(RingSensorAngle(0), DegToRad(7.5), 1e-12);
  EXPECT_NEAR(RingSensorAngle(11), DegToRad(172.5), 1e-12);
  EXPECT_NEAR(RingSensorAngle(12), DegToRad(-172.5), 1e-12);
  EXPECT_NEAR(RingSensorAngle(23), DegToRad(-7.5), 1e-12);
}

TEST(Proximity, WallAtKnownDistanceAndAngle) {
  TempDir d;
  d.Write("c.lua", "function init() end function step() end");
  // Wall face at x = r + 0.05: 5 cm in front of the body.
  const double face = kR + 0.05;
  std::string arena = FootBot("fb0", 0, 0, 0, "c") + Box("wall", face + 0.05, 0, 0.1, 4, 0.5);
  Scene s = Load(d, Experiment(arena, Controller("c.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 1);
  const double* v = s.world->robots[0].rd.proximity;
  for (int k = 0; k < 24; ++k) {
    const double a = RingSensorAngle(k);
    const double expect = std::cos(a) > 0 ? Expected(ToPlaneX(a, face)) : 0.0;
    EXPECT_NEAR(v[k], expect, 1e-5) << "sensor " << k + 1;
  }
  // Hand-computed: sensor 1 (7.5°) sees the wall at 0.135036758/cos(7.5°) − r = 0.0511652 m.
  EXPECT_NEAR(v[0], 0.0100527 / (0.0511652 + 0.000163144), 1e-5);
  EXPECT_NEAR(v[0], v[23], 1e-6);  // symmetric about the heading
  EXPECT_GT(v[2], 0);              // 37.5°: 0.0852 m
  EXPECT_EQ(v[3], 0);              // 52.5°: 0.137 m, out of range
}

TEST(Proximity, RotatedRobotSeesTheWallOnItsSide) {
  TempDir d;
  d.Write("c.lua", "function init() end function step() end");
  // Robot facing +Y (yaw 90°): the wall at +X is on its right, around sensor 18 (−97.5°)
  // and 19 (−82.5°).
  const double face = kR + 0.03;
  std::string arena = FootBot("fb0", 0, 0, 90, "c") + Box("wall", face + 0.05, 0, 0.1, 4, 0.5);
  Scene s = Load(d, Experiment(arena, Controller("c.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 1);
  const double* v = s.world->robots[0].rd.proximity;
  for (int k = 0; k < 24; ++k) {
    const double world = RingSensorAngle(k) + kPi / 2;
    const double expect = std::cos(world) > 0 ? Expected(ToPlaneX(world, face)) : 0.0;
    EXPECT_NEAR(v[k], expect, 1e-5) << "sensor " << k + 1;
  }
  EXPECT_NEAR(v[17], 0.0100527 / ((face / std::cos(DegToRad(7.5)) - kR) + 0.000163144), 1e-5);
  EXPECT_EQ(v[0], 0);
}

TEST(Proximity, AnotherRobot) {
  TempDir d;
  d.Write("c.lua", "function init() end function step() end");
  // Centres 0.24 m apart: 0.07 m between the bodies along the line of centres.
  std::string arena = FootBot("fb0", 0, 0, 0, "c") + FootBot("fb1", 0.24, 0, 0, "c");
  Scene s = Load(d, Experiment(arena, Controller("c.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 1);
  const double* v = s.world->robots[0].rd.proximity;
  for (int k = 0; k < 24; ++k) {
    const double expect = Expected(ToCircle(RingSensorAngle(k), 0.24, 0, kR));
    EXPECT_NEAR(v[k], expect, 1e-5) << "sensor " << k + 1;
  }
  EXPECT_GT(v[0], 0.1);
  EXPECT_EQ(v[1], 0);  // 22.5° passes beside the other body
  // The other robot sees this one behind it (sensors 12 and 13), not itself.
  const double* w = s.world->robots[1].rd.proximity;
  EXPECT_NEAR(w[11], v[0], 1e-5);
  EXPECT_NEAR(w[12], v[23], 1e-5);
  EXPECT_EQ(w[0], 0);
}

TEST(Proximity, ObstaclesBelowTheRayHeightAreNotSeen) {
  TempDir d;
  d.Write("c.lua", "function init() end function step() end");
  // 5 cm high: under the 6 cm rays.
  std::string arena = FootBot("fb0", 0, 0, 0, "c") + Box("low", kR + 0.05 + 0.05, 0, 0.1, 4, 0.05);
  Scene s = Load(d, Experiment(arena, Controller("c.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 1);
  for (double v : s.world->robots[0].rd.proximity) EXPECT_EQ(v, 0);
}

TEST(Proximity, NoiseIsAddedToEverySensorThenClamped) {
  TempDir d;
  d.Write("c.lua", "function init() end function step() end");
  std::string xml = Experiment(FootBot("fb0", 0, 0, 0, "c"), Controller("c.lua", "noise_level=\"0.2\""));
  Scene a = Load(d, xml);
  ASSERT_TRUE(a.ok()) << a.error;
  int positive = 0, zero = 0;
  for (int t = 0; t < 20; ++t) {
    RunTicks(*a.world, 1);
    for (double v : a.world->robots[0].rd.proximity) {
      EXPECT_GE(v, 0);
      EXPECT_LE(v, 0.2);
      positive += v > 0;
      zero += v == 0;
    }
  }
  // Nothing in range: half the draws are negative noise, clamped to 0.
  EXPECT_GT(positive, 150);
  EXPECT_GT(zero, 150);
  // Same seed, same noise.
  Scene b = Load(d, xml);
  RunTicks(*b.world, 20);
  for (int k = 0; k < 24; ++k) EXPECT_EQ(a.world->robots[0].rd.proximity[k], b.world->robots[0].rd.proximity[k]);
}

TEST(Proximity, NegativeNoiseLevelIsALoadError) {
  TempDir d;
  d.Write("c.lua", "function init() end function step() end");
  Scene s = Load(d, Experiment(FootBot("fb0", 0, 0, 0, "c"), Controller("c.lua", "noise_level=\"-0.1\"")));
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.error.find("noise_level"), std::string::npos) << s.error;
}

TEST(Proximity, LuaTablesAreValueAngleUpdatedInPlace) {
  TempDir d;
  d.Write("c.lua", R"(
function init()
  assert(#robot.proximity == 24)
  for i = 1, 24 do
    local p = robot.proximity[i]
    assert(p.value == 0, "init sees 0")
    local expect = math.rad(7.5 + 15 * (i - 1)); if expect > math.pi then expect = expect - 2 * math.pi end
    assert(math.abs(p.angle - expect) < 1e-12, i)
  end
  first = robot.proximity[1]
end
function step()
  assert(robot.proximity[1] == first, "same inner table every step")
  assert(first.value > 0.195 and first.value < 0.197, first.value)
  assert(robot.proximity[12].value == 0)
  log(string.format("%.6f", robot.proximity[24].value))
end
)");
  std::string arena = FootBot("fb0", 0, 0, 0, "c") + Box("wall", kR + 0.05 + 0.05, 0, 0.1, 4, 0.5);
  std::vector<std::string> lines;
  SimOptions so;
  so.log_sink = [&](char, const std::string& l, const LogOrigin&) { lines.push_back(l); };
  Scene s = Load(d, Experiment(arena, Controller("c.lua")), {}, so);
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 3);
  ASSERT_TRUE(s.world->controller_errors.empty()) << s.world->controller_errors[0].message;
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "0.195851");  // 0.0100527 / (0.0511652 + 0.000163144)
}

}  // namespace
}  // namespace essaim
