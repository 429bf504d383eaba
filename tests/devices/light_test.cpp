// Light sensor: exp(−2d) falloff with the intensity-scaled 3D distance, the
// 13-sensor spread 1 − 2Δ/π, additive lights, clamp, 2.5 cut-off, occlusion by boxes and
// robots along the rising 3D ray, the Lua layout.
#include <gtest/gtest.h>

#include <cmath>

#include "devices/devices.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

struct Light {
  double x, y, z, intensity;
};

std::string LightXml(int i, const Light& l) {
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "<light id=\"l%d\" position=\"%.9g,%.9g,%.9g\" orientation=\"0,0,0\" color=\"yellow\" "
                "intensity=\"%.9g\" medium=\"leds\"/>",
                i, l.x, l.y, l.z, l.intensity);
  return buf;
}

std::string Xml(const std::string& arena, const std::string& noise = "0") {
  return "<argos-configuration>\n"
         "  <framework><experiment length=\"1\" ticks_per_second=\"10\" random_seed=\"3\"/></framework>\n"
         "  <controllers><lua_controller id=\"c\"><actuators><differential_steering implementation=\"default\"/>"
         "</actuators><sensors><footbot_light implementation=\"rot_z_only\" show_rays=\"false\" noise_level=\"" +
         noise +
         "\"/></sensors><params script=\"c.lua\"/></lua_controller></controllers>\n"
         "  <arena size=\"10,10,1\" center=\"0,0,0.5\">" +
         arena +
         "</arena>\n"
         "  <physics_engines><dynamics2d id=\"dyn2d\"/></physics_engines>\n"
         "  <media><led id=\"leds\"/></media>\n"
         "</argos-configuration>\n";
}

/// Robot fb0 at the origin with heading `yaw_deg`, the lights, and more arena XML; one tick.
Scene RunScene(const TempDir& d, double yaw_deg, const std::vector<Light>& lights, const std::string& more = "",
               const std::string& noise = "0") {
  d.Write("c.lua", "function init() end function step() end");
  std::string arena = FootBot("fb0", 0, 0, yaw_deg, "c") + more;
  for (size_t i = 0; i < lights.size(); ++i) arena += LightXml(static_cast<int>(i), lights[i]);
  Scene s = Load(d, Xml(arena, noise));
  if (s.ok()) RunTicks(*s.world, 1);
  return s;
}

/// The spec's law for a robot at the origin: sum over lights, then clamp.
void Expected(double yaw, const std::vector<Light>& lights, double out[24]) {
  for (int k = 0; k < 24; ++k) out[k] = 0;
  for (const Light& l : lights) {
    const double d = std::sqrt(l.x * l.x + l.y * l.y + l.z * l.z) / l.intensity;
    if (d > 2.5) continue;
    const double base = std::exp(-2 * d);
    const double bearing = std::atan2(l.y, l.x) - yaw;
    for (int k = 0; k < 24; ++k) {
      const double delta = std::fabs(WrapSigned(bearing - RingSensorAngle(k)));
      if (delta < kPi / 2) out[k] += base * (1 - 2 * delta / kPi);
    }
  }
  for (int k = 0; k < 24; ++k) out[k] = std::min(1.0, out[k]);
}

void ExpectReadings(const Scene& s, double yaw, const std::vector<Light>& lights) {
  double expect[24];
  Expected(yaw, lights, expect);
  for (int k = 0; k < 24; ++k) EXPECT_NEAR(s.world->robots[0].rd.light[k], expect[k], 1e-6) << "sensor " << k + 1;
}

TEST(Light, FalloffAndThirteenSensorSpread) {
  TempDir d;
  const std::vector<Light> lights = {{1, 0, 0.5, 1}};
  Scene s = RunScene(d, 0, lights);
  ASSERT_TRUE(s.ok()) << s.error;
  const double* v = s.world->robots[0].rd.light;
  const double base = std::exp(-2 * std::sqrt(1.25));  // 3D distance to the light
  EXPECT_NEAR(v[0], base * (1 - 7.5 / 90), 1e-6);      // sensor 1 at 7.5°
  EXPECT_NEAR(v[23], base * (1 - 7.5 / 90), 1e-6);     // sensor 24 at −7.5°
  EXPECT_NEAR(v[1], base * 0.75, 1e-6);                // 22.5°
  EXPECT_NEAR(v[5], base * (1 - 82.5 / 90), 1e-6);     // 82.5°: last lit
  EXPECT_EQ(v[6], 0);                                  // 97.5°
  EXPECT_EQ(v[17], 0);
  int lit = 0;
  for (int k = 0; k < 24; ++k) lit += v[k] > 0;
  EXPECT_EQ(lit, 12);
  ExpectReadings(s, 0, lights);
}

TEST(Light, BearingIsRelativeToTheHeadingAndNotOnASensor) {
  TempDir d;
  // Light at 30° in the world, robot heading 100°: bearing −70°, between sensors.
  const std::vector<Light> lights = {{1.2 * std::cos(DegToRad(30)), 1.2 * std::sin(DegToRad(30)), 0, 1}};
  Scene s = RunScene(d, 100, lights);
  ASSERT_TRUE(s.ok()) << s.error;
  ExpectReadings(s, DegToRad(100), lights);
  // Sensor 20 at −67.5°: Δ = 2.5°.
  EXPECT_NEAR(s.world->robots[0].rd.light[19], std::exp(-2.4) * (1 - 2.5 / 90), 1e-6);
}

TEST(Light, WrapsAroundBehindTheRobot) {
  TempDir d;
  // Robot facing +Y, light at −Y: bearing ±π, sensors 12 and 13 brightest.
  const std::vector<Light> lights = {{0, -2, 0, 2}};
  Scene s = RunScene(d, 90, lights);
  ASSERT_TRUE(s.ok()) << s.error;
  ExpectReadings(s, kPi / 2, lights);
  EXPECT_NEAR(s.world->robots[0].rd.light[11], std::exp(-2.0) * (1 - 7.5 / 90), 1e-6);
  EXPECT_NEAR(s.world->robots[0].rd.light[12], std::exp(-2.0) * (1 - 7.5 / 90), 1e-6);
}

TEST(Light, LightsAddUpAndClamp) {
  TempDir d;
  {
    const std::vector<Light> lights = {{2, 0, 0, 1}, {1.5 * std::cos(1.0), 1.5 * std::sin(1.0), 0, 1}};
    Scene s = RunScene(d, 0, lights);
    ASSERT_TRUE(s.ok()) << s.error;
    ExpectReadings(s, 0, lights);
    const double* v = s.world->robots[0].rd.light;
    const double both = std::exp(-4.0) * (1 - 2 * RingSensorAngle(2) / kPi) +
                        std::exp(-3.0) * (1 - 2 * std::fabs(1.0 - RingSensorAngle(2)) / kPi);
    EXPECT_NEAR(v[2], both, 1e-6);
  }
  {
    TempDir d2;
    const std::vector<Light> lights = {{0.2, 0, 0, 1}, {0.2, 0.05, 0, 1}};
    Scene s = RunScene(d2, 0, lights);
    ASSERT_TRUE(s.ok()) << s.error;
    EXPECT_EQ(s.world->robots[0].rd.light[0], 1.0);  // 0.61 + 0.63 clamped
    ExpectReadings(s, 0, lights);
  }
}

TEST(Light, IntensityScalesDistanceAndFarOrDarkLightsAreIgnored) {
  TempDir d;
  Scene a = RunScene(d, 0, {{2, 0, 0, 2}});  // d = 1
  ASSERT_TRUE(a.ok()) << a.error;
  EXPECT_NEAR(a.world->robots[0].rd.light[0], std::exp(-2.0) * (1 - 7.5 / 90), 1e-6);
  TempDir d2;
  Scene b = RunScene(d2, 0, {{2.6, 0, 0, 1}, {0.5, 0, 0, 0}});  // beyond 2.5; intensity 0
  ASSERT_TRUE(b.ok()) << b.error;
  for (double v : b.world->robots[0].rd.light) EXPECT_EQ(v, 0);
}

TEST(Light, OccludedByABox) {
  TempDir d;
  Scene s = RunScene(d, 0, {{2, 0, 0.5, 1}}, Box("b", 1, 0, 0.2, 0.2, 0.5));
  ASSERT_TRUE(s.ok()) << s.error;
  for (double v : s.world->robots[0].rd.light) EXPECT_EQ(v, 0);
  // A box off the line does not occlude.
  TempDir d2;
  Scene t = RunScene(d2, 0, {{2, 0, 0.5, 1}}, Box("b", 1, 0.5, 0.2, 0.2, 0.5));
  ASSERT_TRUE(t.ok()) << t.error;
  ExpectReadings(t, 0, {{2, 0, 0.5, 1}});
}

TEST(Light, TheRayRisesTowardsAnElevatedLight) {
  // Light 1 m up, 2 m away. A 10 cm box near the light is under the ray (ray height
  // 0.7 m there); the same box near the robot is not (ray height 0.075 m at its face).
  const std::vector<Light> lights = {{2, 0, 1.0, 1}};
  TempDir d;
  Scene far = RunScene(d, 0, lights, Box("b", 1.5, 0, 0.2, 0.2, 0.1));
  ASSERT_TRUE(far.ok()) << far.error;
  ExpectReadings(far, 0, lights);
  EXPECT_GT(far.world->robots[0].rd.light[0], 0);
  TempDir d2;
  Scene near = RunScene(d2, 0, lights, Box("b", 0.25, 0, 0.2, 0.2, 0.1));
  ASSERT_TRUE(near.ok()) << near.error;
  for (double v : near.world->robots[0].rd.light) EXPECT_EQ(v, 0);
  // Passing over one shape and meeting the next: low box near the light, tall one beyond.
  TempDir d3;
  Scene both = RunScene(d3, 0, lights, Box("b", 1.0, 0, 0.2, 0.2, 0.1) + Box("c", 1.6, 0, 0.2, 0.2, 1.0));
  ASSERT_TRUE(both.ok()) << both.error;
  for (double v : both.world->robots[0].rd.light) EXPECT_EQ(v, 0);
}

TEST(Light, OtherRobotsOccludeLowLights) {
  TempDir d;
  // Ray height at the other robot's body: 0.1 · 0.915 / 2 ≈ 0.046 m < 0.147 m.
  Scene s = RunScene(d, 0, {{2, 0, 0.1, 1}}, FootBot("fb1", 1, 0, 0, "c"));
  ASSERT_TRUE(s.ok()) << s.error;
  for (double v : s.world->robots[0].rd.light) EXPECT_EQ(v, 0);
  // A light 0.5 m up is seen over it (ray ≈ 0.23 m high there), as in ARGoS.
  TempDir d2;
  Scene t = RunScene(d2, 0, {{2, 0, 0.5, 1}}, FootBot("fb1", 1, 0, 0, "c"));
  ASSERT_TRUE(t.ok()) << t.error;
  ExpectReadings(t, 0, {{2, 0, 0.5, 1}});
}

TEST(Light, NoiseThenClamp) {
  TempDir d;
  Scene s = RunScene(d, 0, {{1, 0, 0, 1}}, "", "0.05");
  ASSERT_TRUE(s.ok()) << s.error;
  double expect[24];
  Expected(0, {{1, 0, 0, 1}}, expect);
  int differ = 0;
  for (int k = 0; k < 24; ++k) {
    const double v = s.world->robots[0].rd.light[k];
    EXPECT_GE(v, 0);
    EXPECT_LE(v, 1);
    EXPECT_LE(std::fabs(v - expect[k]), 0.05 + 1e-12);
    differ += v != expect[k];
  }
  EXPECT_GT(differ, 12);
}

TEST(Light, LuaLayoutAndInitSeesZero) {
  TempDir d;
  d.Write("c.lua", R"(
function init()
  assert(#robot.light == 24)
  for i = 1, 24 do assert(robot.light[i].value == 0) end
  assert(math.abs(robot.light[1].angle - math.rad(7.5)) < 1e-12)
  assert(math.abs(robot.light[13].angle + math.rad(172.5)) < 1e-12)
  keep = robot.light[1]
end
function step()
  assert(robot.light[1] == keep)
  assert(math.abs(keep.value - math.exp(-2) * (1 - 7.5 / 90)) < 1e-6, keep.value)
end
)");
  Scene s = Load(d, Xml(FootBot("fb0", 0, 0, 0, "c") + LightXml(0, {1, 0, 0, 1})));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 2);
  ASSERT_TRUE(s.world->controller_errors.empty()) << s.world->controller_errors[0].message;
}

}  // namespace
}  // namespace essaim
