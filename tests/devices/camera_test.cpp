// Colored-blob omnidirectional camera against hand-computed blobs: other
// robots' LEDs, LEDs on boxes, <light>s; black LEDs, the square field of view,
// occlusion, other media and a disabled camera see nothing.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.h"
#include "devices/media.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

constexpr char kSilent[] = "function init() end\nfunction step() end\n";
constexpr char kLook[] =
    "function init() robot.colored_blob_omnidirectional_camera.enable() end\nfunction step() end\n";

std::string CamController(const std::string& id, const std::string& script, bool camera = true) {
  return "<lua_controller id=\"" + id +
         "\"><actuators><differential_steering implementation=\"default\"/>"
         "<leds implementation=\"default\" medium=\"leds\"/></actuators><sensors>" +
         std::string(camera ? "<colored_blob_omnidirectional_camera implementation=\"rot_z_only\" medium=\"leds\"/>"
                            : "") +
         "</sensors><params script=\"" + script + "\"/></lua_controller>";
}

std::string Bot(const std::string& id, double x, double y, double yaw_deg, const std::string& ctrl) {
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "<foot-bot id=\"%s\"><body position=\"%.17g,%.17g,0\" orientation=\"%g,0,0\"/><controller "
                "config=\"%s\"/></foot-bot>",
                id.c_str(), x, y, yaw_deg, ctrl.c_str());
  return buf;
}

std::string CamExperiment(const std::string& arena, const std::string& controllers) {
  std::string xml = Experiment(arena, controllers, 1000);
  size_t p = xml.find("<media/>");
  xml.replace(p, 8, "<media><led id=\"leds\"/><led id=\"other\"/></media>");
  return xml;
}

std::string Beacon(const std::string& colour) {
  return "function init() robot.leds.set_single_color(13, '" + colour + "') end\nfunction step() end\n";
}

const std::vector<Blob>& Blobs(const Scene& s, int r = 0) { return s.world->robots[r].rd.blobs; }

bool Rgb(const Color& c, int r, int g, int b) { return c.r == r && c.g == g && c.b == b; }

TEST(Camera, BeaconOfAnotherRobot) {
  TempDir d;
  d.Write("look.lua", kLook);
  d.Write("green.lua", Beacon("green"));
  for (double yaw : {0.0, 90.0}) {
    Scene s = Load(d, CamExperiment(Bot("cam", 0, 0, yaw, "look") + Bot("b", 0.5, 0.3, 0, "green"),
                                    CamController("look", "look.lua") + CamController("green", "green.lua", false)));
    ASSERT_TRUE(s.ok()) << s.error;
    EXPECT_TRUE(Blobs(s).empty());
    Step(*s.world);  // the LED set in init is lit from tick 1 on
    ASSERT_EQ(Blobs(s).size(), 1u);
    const Blob& b = Blobs(s)[0];
    EXPECT_NEAR(b.distance, 58.30951895, 1e-4);  // planar, cm
    EXPECT_NEAR(b.angle, 0.54041950027 - DegToRad(yaw), 1e-6);
    EXPECT_TRUE(Rgb(b.color, 0, 255, 0));
    EXPECT_TRUE(Blobs(s, 1).empty());  // b has no camera
  }
}

/// Whether the segment origin -> p crosses the disc (c, r).
bool SegmentHitsDisc(const Vec2& p, const Vec2& c, double r) {
  double t = std::clamp(c.dot(p) / p.squaredNorm(), 0.0, 1.0);
  return (t * p - c).norm() < r;
}

TEST(Camera, RingLedsBehindTheirRobotAreHidden) {
  TempDir d;
  d.Write("look.lua", kLook);
  d.Write("red.lua", "function init() robot.leds.set_all_colors('red') end\nfunction step() end\n");
  Scene s = Load(d, CamExperiment(Bot("cam", 0, 0, 0, "look") + Bot("b", 0.5, 0, 0, "red"),
                                  CamController("look", "look.lua") + CamController("red", "red.lua", false)));
  ASSERT_TRUE(s.ok()) << s.error;
  Step(*s.world);
  // Expected: ring LEDs whose sight line misses b's body, then the beacon (above bodies).
  std::vector<double> expect;
  for (int i = 0; i < 12; ++i) {
    double a = DegToRad(15 + 30 * i);
    Vec2 p(0.5 + 0.090036758 * std::cos(a), 0.090036758 * std::sin(a));
    if (!SegmentHitsDisc(p, Vec2(0.5, 0), 0.085036758)) expect.push_back(p.norm() * 100);
  }
  expect.push_back(50);
  ASSERT_EQ(expect.size(), 7u);  // LEDs 5..10 face the camera
  ASSERT_EQ(Blobs(s).size(), expect.size());
  for (size_t k = 0; k < expect.size(); ++k) {
    EXPECT_NEAR(Blobs(s)[k].distance, expect[k], 1e-4) << k;
    EXPECT_TRUE(Rgb(Blobs(s)[k].color, 255, 0, 0));
  }
}

TEST(Camera, BoxLedsAndLights) {
  TempDir d;
  d.Write("look.lua", kLook);
  const std::string box =
      "<box id=\"bx\" size=\"0.1,0.1,0.1\" movable=\"false\"><body position=\"0.4,-0.4,0\" orientation=\"30,0,0\"/>"
      "<leds medium=\"leds\"><led offset=\"0,0,0.1\" anchor=\"origin\" color=\"blue\"/>"
      "<led offset=\"0.02,0,0.1\" anchor=\"origin\" color=\"black\"/></leds></box>";
  const std::string lights =
      "<light id=\"l0\" position=\"-0.3,0.2,0.2\" orientation=\"0,0,0\" color=\"yellow\" intensity=\"1\" "
      "medium=\"leds\"/>"
      "<light id=\"l1\" position=\"-0.3,-0.2,0.2\" orientation=\"0,0,0\" color=\"red\" intensity=\"1\" "
      "medium=\"other\"/>"
      "<light id=\"l2\" position=\"0.3,0.3,0.5\" orientation=\"0,0,0\" color=\"red\" intensity=\"1\" medium=\"leds\"/>"
      "<light id=\"l3\" position=\"-0.3,0.3,0.6\" orientation=\"0,0,0\" color=\"green\" intensity=\"1\" "
      "medium=\"leds\"/>";
  Scene s = Load(d, CamExperiment(Bot("cam", 0, 0, 0, "look") + box + lights, CamController("look", "look.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  Step(*s.world);
  // The box LED (on its own top face: not hidden by it), then the lights l0 and l2: ARGoS
  // sees an LED less than the camera's height above the camera (0.5 m - 0.289 m < 0.289 m),
  // not l3 (0.6 m). The black LED and the light of another medium are not seen. Box LEDs
  // come before lights.
  ASSERT_EQ(Blobs(s).size(), 3u);
  EXPECT_NEAR(Blobs(s)[0].distance, 56.56854249, 1e-4);
  EXPECT_NEAR(Blobs(s)[0].angle, -kPi / 4, 1e-6);
  EXPECT_TRUE(Rgb(Blobs(s)[0].color, 0, 0, 255));
  EXPECT_NEAR(Blobs(s)[1].distance, 36.05551275, 1e-4);
  EXPECT_NEAR(Blobs(s)[1].angle, 2.55359005004, 1e-6);
  EXPECT_TRUE(Rgb(Blobs(s)[1].color, 255, 255, 0));
  EXPECT_NEAR(Blobs(s)[2].distance, 42.42640687, 1e-4);
  EXPECT_NEAR(Blobs(s)[2].angle, kPi / 4, 1e-6);
  EXPECT_TRUE(Rgb(Blobs(s)[2].color, 255, 0, 0));
}

TEST(Camera, SquareFieldOfViewAndOcclusion) {
  TempDir d;
  d.Write("look.lua", kLook);
  d.Write("green.lua", Beacon("green"));
  // h = 0.288699733 · tan 70° = 0.7932 m. (0.7, 0.7) is 0.99 m away but inside the square;
  // (0.85, 0) is outside; (0, -0.78) inside. A 0.5 m box hides the beacon at (-0.5, 0.3).
  const std::string tall =
      "<box id=\"t\" size=\"0.1,0.1,0.5\" movable=\"false\"><body position=\"-0.25,0.15,0\" "
      "orientation=\"0,0,0\"/></box>";
  Scene s = Load(
      d, CamExperiment(Bot("cam", 0, 0, 0, "look") + Bot("b1", 0.7, 0.7, 0, "green") + Bot("b2", 0.85, 0, 0, "green") +
                           Bot("b3", 0, -0.78, 0, "green") + Bot("b4", -0.5, 0.3, 0, "green") + tall,
                       CamController("look", "look.lua") + CamController("green", "green.lua", false)));
  ASSERT_TRUE(s.ok()) << s.error;
  Step(*s.world);
  ASSERT_EQ(Blobs(s).size(), 2u);
  EXPECT_NEAR(Blobs(s)[0].distance, 98.99494937, 1e-4);
  EXPECT_NEAR(Blobs(s)[0].angle, kPi / 4, 1e-6);
  EXPECT_NEAR(Blobs(s)[1].distance, 78, 1e-4);
  EXPECT_NEAR(Blobs(s)[1].angle, -kPi / 2, 1e-6);
}

TEST(Camera, BlackLedsAndDisabledCameraSeeNothing) {
  TempDir d;
  d.Write("dark.lua", kSilent);
  d.Write("green.lua", Beacon("green"));
  d.Write("blind.lua", kSilent);
  // Enabled at init, disabled during step 2: blobs at steps 1-2, none (and nil) after.
  d.Write("blink.lua",
          "n = 0\nfunction init() robot.colored_blob_omnidirectional_camera.enable() end\n"
          "function step() n = n + 1; local cam = robot.colored_blob_omnidirectional_camera\n"
          "  local b = cam[1]\n"
          "  print(#cam, b and (b.color.red .. ',' .. b.color.green .. ',' .. b.color.blue .. ' ' .. "
          "math.type(b.color.green)) or 'nil')\n"
          "  if n == 2 then cam.disable() end end\n");
  d.Write("look.lua", kLook);
  std::vector<std::string> lines;
  SimOptions sim;
  sim.log_sink = [&lines](char, const std::string& line, const LogOrigin&) { lines.push_back(line); };
  Scene s = Load(
      d,
      CamExperiment(Bot("look", 0, 0, 0, "look") + Bot("dark", 0.4, 0, 0, "dark") + Bot("blind", 0, 0.4, 0, "blind") +
                        Bot("blink", -0.4, 0, 0, "blink") + Bot("g", -0.4, -0.4, 0, "green"),
                    CamController("look", "look.lua") + CamController("dark", "dark.lua", false) +
                        CamController("blind", "blind.lua") + CamController("blink", "blink.lua") +
                        CamController("green", "green.lua", false)),
      {}, sim);
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 4);
  ASSERT_EQ(Blobs(s, 0).size(), 1u);  // only g's beacon: dark's LEDs are black
  EXPECT_TRUE(Rgb(Blobs(s, 0)[0].color, 0, 255, 0));
  EXPECT_TRUE(Blobs(s, 2).empty());  // never enabled
  EXPECT_TRUE(Blobs(s, 3).empty());
  EXPECT_EQ(lines, std::vector<std::string>({"1\t0,255,0 integer", "1\t0,255,0 integer", "0\tnil", "0\tnil"}));
}

TEST(Camera, NoiseIsDeterministic) {
  TempDir d;
  d.Write("look.lua", kLook);
  d.Write("green.lua", Beacon("green"));
  std::string xml = CamExperiment(Bot("cam", 0, 0, 0, "look") + Bot("b", 0.5, 0, 0, "green"),
                                  CamController("look", "look.lua") + CamController("green", "green.lua", false));
  xml.replace(xml.find("medium=\"leds\"/></sensors>"), 0, "noise_std_dev=\"0.1\" ");
  std::vector<double> first;
  double sum = 0;
  for (int run = 0; run < 2; ++run) {
    Scene s = Load(d, xml);
    ASSERT_TRUE(s.ok()) << s.error;
    for (int t = 0; t < 200; ++t) {
      Step(*s.world);
      double dist = Blobs(s).at(0).distance;
      if (run == 0)
        first.push_back(dist), sum += dist;
      else
        ASSERT_EQ(first[static_cast<size_t>(t)], dist);
    }
  }
  EXPECT_NE(first[0], first[1]);
  EXPECT_NEAR(sum / 200, 50.0, 1.5);
}

TEST(Camera, OcclusionRaysMatchBox2D) {
  // The camera's occlusion rays (media grids, exact circle/box tests) must answer what
  // PhysicsWorld::CastRay answers, at ring, beacon and tall-obstacle heights.
  TempDir d;
  d.Write("look.lua", kLook);
  Rng rng(5);
  std::string arena;
  std::vector<Vec2> taken;
  auto spot = [&](double clearance) {
    Vec2 p;
    bool ok;
    do {
      p = Vec2(rng.Uniform(-3, 3), rng.Uniform(-3, 3));
      ok = true;
      for (const Vec2& q : taken) ok &= (p - q).norm() > clearance;
    } while (!ok);
    taken.push_back(p);
    return p;
  };
  for (int k = 0; k < 30; ++k) {
    Vec2 p = spot(0.45);
    char buf[256];
    if (k % 3 == 0)
      std::snprintf(buf, sizeof buf,
                    "<cylinder id=\"c%d\" radius=\"0.1\" height=\"%s\" movable=\"false\"><body position=\"%g,%g,0\" "
                    "orientation=\"0,0,0\"/></cylinder>",
                    k, k % 2 ? "0.1" : "0.5", p.x(), p.y());
    else
      std::snprintf(buf, sizeof buf,
                    "<box id=\"b%d\" size=\"0.3,0.08,%s\" movable=\"%s\" mass=\"1\"><body position=\"%g,%g,0\" "
                    "orientation=\"%d,0,0\"/></box>",
                    k, k % 4 == 1 ? "0.12" : "0.4", k % 2 ? "true" : "false", p.x(), p.y(), k * 41);
    arena += buf;
  }
  arena +=
      "<box id=\"wall\" size=\"8,0.1,0.5\" movable=\"false\"><body position=\"0,3.3,0\" orientation=\"0,0,0\"/></box>";
  for (int i = 0; i < 150; ++i) {
    Vec2 p = spot(0.3);
    arena += Bot("fb" + std::to_string(i), p.x(), p.y(), 0, "look");
  }
  Scene s = Load(d, CamExperiment(arena, CamController("look", "look.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  Step(*s.world);
  const World& w = *s.world;
  int blocked = 0, clear = 0;
  for (int k = 0; k < 20000; ++k) {
    const int self = static_cast<int>(rng.Uniform(0, 149.999));
    const Pose2 p = w.physics.RobotPose(self);
    const Vec2 from(p.x, p.y);
    const Vec2 to = from + Vec2(rng.Uniform(-1.1, 1.1), rng.Uniform(-1.1, 1.1));
    const double z = k % 3 == 0 ? 0.085 : k % 3 == 1 ? 0.174249733 : 0.3;
    // A level segment: ARGoS's 3D rule then reduces to CastRay's (a shape is hit where the
    // ray enters it if its heights span z), gripper discs included on both sides.
    const bool ours =
        CameraRayBlocked(w.model, w.media, Vec3(from.x(), from.y(), z), Vec3(to.x(), to.y(), z), self, -1);
    const bool box2d = w.physics.CastRay(from, to, z, self).Hit();
    ASSERT_EQ(ours, box2d) << "ray " << k << " from robot " << self << " to " << to.transpose() << " z " << z;
    (ours ? blocked : clear)++;
  }
  EXPECT_GT(blocked, 3000);
  EXPECT_GT(clear, 3000);
}

}  // namespace
}  // namespace essaim
