// Snapshots (render/render_cairo.cpp): a scene with known contents is recorded, drawn and read
// back with libpng; pixels are checked where the robot, the box, the floor's corners and a
// trail must be. The arena is off-centre and twice as wide as tall, so a flipped or
// stretched image fails.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "model/floor_image.h"
#include "output/atomic_file.h"
#include "output/recording.h"
#include "support/scene.h"
#ifdef ESSAIM_HAVE_CAIRO
#include "render/render_cairo.h"
#endif

namespace essaim {
namespace {
using namespace essaim::testing;

#ifdef ESSAIM_HAVE_CAIRO

const char* kPlainController =
    "<lua_controller id=\"p\"><actuators><differential_steering implementation=\"default\"/></actuators>"
    "<sensors/><params script=\"" ESSAIM_SOURCE_DIR "/tests/support/idle.lua\"/></lua_controller>";

/// Arena 4 m × 2 m centred at (1, 0.5): x in [-1, 3], y in [-0.5, 1.5]. The floor is blue
/// in its bottom-left quarter (x < 0, y < 0), white elsewhere.
std::string SnapshotExperiment() {
  return "<argos-configuration>\n"
         "  <framework><experiment length=\"10\" ticks_per_second=\"10\" random_seed=\"1\"/></framework>\n"
         "  <controllers>" +
         std::string(kPlainController) +
         "</controllers>\n"
         "  <loop_functions script=\"floor.lua\"/>\n"
         "  <arena size=\"4,2,1\" center=\"1,0.5,0.5\">\n"
         "    <floor id=\"f\" source=\"loop_functions\" pixels_per_meter=\"100\"/>\n"
         "    <box id=\"crate\" size=\"0.3,0.3,0.2\" movable=\"false\"><body position=\"0.5,-0.1,0\" "
         "orientation=\"0,0,0\"/></box>\n"
         "    " +
         FootBot("red", 1.5, 1.005, 0, "p") +
         "\n"
         "    " +
         FootBot("ghost", -0.5, 1.0, 90, "p") +
         "\n"
         "  </arena>\n"
         "  <physics_engines><dynamics2d id=\"dyn2d\" iterations=\"10\"/></physics_engines>\n"
         "  <media/>\n"
         "</argos-configuration>\n";
}

struct Image {
  int width = 0, height = 0;
  std::vector<Color> pixels;  // bottom row first
  Vec2 min = Vec2::Zero();
  double px_per_m = 1;
  /// The pixel under world point (x, y).
  Color At(double x, double y) const {
    int col = static_cast<int>(std::floor((x - min.x()) * px_per_m));
    int row = static_cast<int>(std::floor((y - min.y()) * px_per_m));
    return pixels[static_cast<size_t>(row) * width + col];
  }
};

class Snapshot : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_.Write("floor.lua",
               "function floor_color(x, y) if x < 0 and y < 0 then return 0, 0, 255 end return 255, 255, 255 end\n");
    Scene s = Load(dir_, SnapshotExperiment());
    ASSERT_TRUE(s.ok()) << s.error;
    World& w = *s.world;
    for (Color& c : w.robots[0].leds) c = Color{255, 0, 0, 255};  // all LEDs red
    w.robots[0].cmd.wheel_left = w.robots[0].cmd.wheel_right = 0.2;
    w.robots[0].cmd.wheels_new = true;
    w.robots[1].alive = false;  // shown greyed
    std::string error;
    RecordingWriter writer;
    ASSERT_TRUE(writer.Open(dir_.path() + "/recording.bin", w, 1, &error)) << error;
    for (int t = 0; t < 30; ++t) {
      Step(w);
      writer.Record(w);
    }
    ASSERT_TRUE(writer.Finish(w, &error)) << error;
    ASSERT_TRUE(Recording::Read(dir_.path() + "/recording.bin", &rec_, &error)) << error;
  }

  Image Render(size_t frame, int trail, int size = 400, bool labels = false) {
    SnapshotOptions opt;
    opt.size = size;
    opt.trail_ticks = trail;
    opt.labels = labels;
    std::string png, error;
    Image img;
    EXPECT_TRUE(RenderSnapshotPng(rec_, frame, opt, &png, &error)) << error;
    std::string path = dir_.path() + "/snap.png";
    EXPECT_TRUE(WriteFileAtomic(path, png, &error)) << error;
    EXPECT_TRUE(LoadPngBottomUp(path, 1 << 26, &img.width, &img.height, &img.pixels, &error)) << error;
    img.min = rec_.scene().arena_min;
    img.px_per_m = img.width / rec_.scene().arena_size.x();
    return img;
  }

  TempDir dir_;
  Recording rec_;
};

bool Near(Color c, int r, int g, int b, int tol = 2) {
  return std::abs(c.r - r) <= tol && std::abs(c.g - g) <= tol && std::abs(c.b - b) <= tol;
}
std::string Str(Color c) {
  return "(" + std::to_string(c.r) + "," + std::to_string(c.g) + "," + std::to_string(c.b) + ")";
}

/// Pixels of the text (black, anti-aliased) in a box of the image: darker than mid-grey.
int DarkPixels(const Image& img, double x0, double y0, double x1, double y1) {
  int dark = 0;
  for (double y = y0; y < y1; y += 0.5 / img.px_per_m)
    for (double x = x0; x < x1; x += 0.5 / img.px_per_m) dark += Near(img.At(x, y), 0, 0, 0, 128);
  return dark;
}

TEST_F(Snapshot, LabelsShowTheTickTopLeftAndEachRobotsIdBesideIt) {
  size_t last = rec_.FrameCount() - 1;
  RecordedRobot ghost = rec_.Robot(last, 1);
  Image plain = Render(last, 0, 800, false), labelled = Render(last, 0, 800, true);
  // The tick: the top-left corner (white floor there) holds text only with labels.
  EXPECT_EQ(DarkPixels(plain, -1.0, 1.3, -0.3, 1.5), 0);
  EXPECT_GT(DarkPixels(labelled, -1.0, 1.3, -0.3, 1.5), 20);
  // The ghost's id, up and to the right of its body.
  const double r = rec_.scene().robot_radius;
  EXPECT_EQ(DarkPixels(plain, ghost.x + r, ghost.y + r, ghost.x + 5 * r, ghost.y + 2.5 * r), 0);
  EXPECT_GT(DarkPixels(labelled, ghost.x + r, ghost.y + r, ghost.x + 5 * r, ghost.y + 2.5 * r), 10);
}

TEST_F(Snapshot, ImageKeepsTheArenaAspect) {
  Image img = Render(0, 0, 400);
  EXPECT_EQ(img.width, 400);
  EXPECT_EQ(img.height, 200);
  int w = 0, h = 0;
  SnapshotImageSize(rec_.scene(), 300, &w, &h);
  EXPECT_EQ(w, 300);
  EXPECT_EQ(h, 150);
}

TEST_F(Snapshot, FloorBottomLeftIsTheArenasMinCorner) {
  Image img = Render(0, 0);
  EXPECT_TRUE(Near(img.At(-0.5, -0.25), 0, 0, 255)) << Str(img.At(-0.5, -0.25)) << " bottom-left: blue";
  EXPECT_TRUE(Near(img.At(-0.95, -0.45), 0, 0, 255)) << Str(img.At(-0.95, -0.45)) << " the very corner";
  EXPECT_TRUE(Near(img.At(-0.5, 1.25), 255, 255, 255)) << Str(img.At(-0.5, 1.25)) << " top-left: white";
  EXPECT_TRUE(Near(img.At(2.5, -0.25), 255, 255, 255)) << Str(img.At(2.5, -0.25)) << " bottom-right: white";
  EXPECT_TRUE(Near(img.At(0.1, -0.25), 255, 255, 255)) << Str(img.At(0.1, -0.25)) << " just right of x = 0";
  EXPECT_TRUE(Near(img.At(-0.5, 0.05), 255, 255, 255)) << Str(img.At(-0.5, 0.05)) << " just above y = 0";
}

TEST_F(Snapshot, RobotInItsLedColourAtItsPosition) {
  size_t last = rec_.FrameCount() - 1;
  RecordedRobot r = rec_.Robot(last, 0);
  ASSERT_GT(r.x, 1.9) << "the robot drove";
  Image img = Render(last, 0);
  // Half a radius to the robot's left, clear of its heading line.
  Color c = img.At(r.x - std::sin(r.yaw) * 0.04, r.y + std::cos(r.yaw) * 0.04);
  EXPECT_TRUE(Near(c, 255, 0, 0)) << Str(c);
  c = img.At(r.x - std::sin(r.yaw) * 0.04 - std::cos(r.yaw) * 0.04, r.y + std::cos(r.yaw) * 0.04);
  EXPECT_TRUE(Near(c, 255, 0, 0)) << Str(c) << " behind the centre";
  // Its start, with no trail drawn: floor.
  EXPECT_TRUE(Near(img.At(1.5, 1.005), 255, 255, 255)) << Str(img.At(1.5, 1.005));
  // Outside the body: floor.
  EXPECT_TRUE(Near(img.At(r.x, r.y + 0.15), 255, 255, 255));
}

TEST_F(Snapshot, StaticBoxWhereItStands) {
  Image img = Render(0, 0);
  EXPECT_TRUE(Near(img.At(0.5, -0.1), 0x4d, 0x4d, 0x4d)) << Str(img.At(0.5, -0.1));
  EXPECT_TRUE(Near(img.At(0.62, 0.02), 0x4d, 0x4d, 0x4d)) << Str(img.At(0.62, 0.02)) << " near a corner";
  EXPECT_TRUE(Near(img.At(0.5, 0.1), 255, 255, 255)) << Str(img.At(0.5, 0.1)) << " above the box";
}

TEST_F(Snapshot, DeadRobotIsGrey) {
  Image img = Render(0, 0);
  Color c = img.At(-0.5 + 0.04, 1.0);  // yaw 90°: left of it is -x; right is +x
  EXPECT_LE(std::abs(c.r - c.g), 2) << Str(c);
  EXPECT_LE(std::abs(c.g - c.b), 2) << Str(c);
  EXPECT_GT(c.r, 100);
  EXPECT_LT(c.r, 190);
}

TEST_F(Snapshot, TrailFollowsThePath) {
  size_t last = rec_.FrameCount() - 1;
  Image img = Render(last, 100);
  Color c = img.At(1.55, 1.005);  // on the way, behind the robot
  EXPECT_GT(c.r, 200) << Str(c);
  EXPECT_LT(c.g, 130) << Str(c);
  // A short trail does not reach back there.
  Image shorter = Render(last, 5);
  EXPECT_TRUE(Near(shorter.At(1.55, 1.005), 255, 255, 255)) << Str(shorter.At(1.55, 1.005));
}

/// Non-floor pixels in a box of the image (the floor there is white).
int InkedPixels(const Image& img, double x0, double y0, double x1, double y1) {
  int inked = 0;
  for (double y = y0; y < y1; y += 0.5 / img.px_per_m)
    for (double x = x0; x < x1; x += 0.5 / img.px_per_m) inked += !Near(img.At(x, y), 255, 255, 255, 8);
  return inked;
}

TEST_F(Snapshot, RobotAddedDuringTheRunIsDrawnOnlyOnceThere) {
  dir_.Write("floor.lua",
             "function floor_color(x, y) if x < 0 and y < 0 then return 0, 0, 255 end return 255, 255, 255 end\n"
             "function post_step() if experiment.tick == 10 then\n"
             "  experiment.add_entity('foot-bot', {id = 'late', controller = 'p', position = {1.5, 0.2}})\n"
             "end end\n");
  Scene s = Load(dir_, SnapshotExperiment());
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  std::string error;
  RecordingWriter writer;
  ASSERT_TRUE(writer.Open(dir_.path() + "/recording.bin", w, 1, &error)) << error;
  for (int t = 1; t <= 30; ++t) {
    Step(w);
    if (t == 10) {  // it drives east from where it was added
      ASSERT_EQ(w.robots.size(), 3u);
      w.robots[2].cmd.wheel_left = w.robots[2].cmd.wheel_right = 0.2;
      w.robots[2].cmd.wheels_new = true;
    }
    writer.Record(w);
  }
  ASSERT_TRUE(writer.Finish(w, &error)) << error;
  ASSERT_TRUE(Recording::Read(dir_.path() + "/recording.bin", &rec_, &error)) << error;
  const size_t last = rec_.FrameCount() - 1;
  ASSERT_FALSE(rec_.Robot(5, 2).present);
  const RecordedRobot late = rec_.Robot(last, 2);
  ASSERT_TRUE(late.present);
  ASSERT_GT(late.x, 1.8) << "it drove";

  const double r = rec_.scene().robot_radius;
  Image before = Render(5, 100, 400, true);  // not added yet: no body, no label, no trail
  EXPECT_EQ(InkedPixels(before, 1.5 - r, 0.2 - r, 1.5 + 5 * r, 0.2 + 2.5 * r), 0);
  Image after = Render(last, 100, 400, true);
  EXPECT_TRUE(Near(after.At(late.x, late.y - r / 2), 0xc8, 0xd0, 0xd8)) << Str(after.At(late.x, late.y - r / 2));
  EXPECT_GT(InkedPixels(after, 1.55, 0.18, 1.65, 0.22), 0) << "its trail, from where it was added";
  // The trail starts where it was added: nothing drawn from the frames before (had they
  // been read as poses, a line would come in from far outside the arena on the left).
  EXPECT_EQ(InkedPixels(after, -0.9, 0.15, 1.3, 0.3), 0);
}

#else

TEST(Snapshot, SkippedWithoutCairo) { GTEST_SKIP() << "essaim built without Cairo (libcairo2-dev)"; }

#endif

}  // namespace
}  // namespace essaim
