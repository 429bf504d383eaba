// Recordings (docs/recording.md): a run recorded and read back matches the run's own trace
// within the quantisation (1 mm, 2π/65536 rad, 1/255 of battery); every=N keeps ticks
// 0, N, 2N… and the last; dead flags, battery, LED colour, movable obstacles, the scene and
// the floor are stored; robots the loop functions add during the run are absent from the
// frames before their arrival; the file appears only when the recording is finished.
#include "output/recording.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/paths.h"
#include "core/strings.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

// Robots driven from C++ (controllers without a script keep the commands we write).
const char* kPlainController =
    "<lua_controller id=\"p\"><actuators><differential_steering implementation=\"default\"/></actuators>"
    "<sensors/><params script=\"" ESSAIM_SOURCE_DIR "/tests/support/idle.lua\"/></lua_controller>";

void Wheels(RobotState& r, double left_m_s, double right_m_s) {
  r.cmd.wheel_left = left_m_s;
  r.cmd.wheel_right = right_m_s;
  r.cmd.wheels_new = true;
}

double AngleDiff(double a, double b) { return std::fabs(WrapSigned(a - b)); }

struct Trace {
  std::vector<uint64_t> ticks;
  std::vector<std::vector<Pose2>> poses;  // per tick, per robot
  void Add(const World& w) {
    ticks.push_back(w.tick);
    std::vector<Pose2> p;
    for (int i = 0; i < w.physics.RobotCount(); ++i) p.push_back(w.physics.RobotPose(i));
    poses.push_back(p);
  }
};

Scene ThreeRobots(const TempDir& d, int ticks) {
  std::string arena = FootBot("a", -1, -1, 0, "p") + FootBot("b", 1, 0.5, 90, "p") + FootBot("c", 0, 2, 200, "p");
  Scene s = Load(d, Experiment(arena, kPlainController, ticks));
  if (s.ok()) {
    Wheels(s.world->robots[0], 0.10, 0.15);
    Wheels(s.world->robots[1], 0.20, 0.05);
    Wheels(s.world->robots[2], -0.1, 0.1);
  }
  return s;
}

/// Runs `ticks` ticks recording every `every`, returning the trace of every tick.
Trace RecordRun(World& w, const std::string& path, uint32_t every, int ticks) {
  Trace trace;
  RecordingWriter rec;
  std::string error;
  EXPECT_TRUE(rec.Open(path, w, every, &error)) << error;
  trace.Add(w);
  for (int t = 0; t < ticks; ++t) {
    Step(w);
    rec.Record(w);
    trace.Add(w);
  }
  EXPECT_TRUE(rec.Finish(w, &error)) << error;
  return trace;
}

void ExpectFrameMatches(const Recording& rec, size_t frame, const std::vector<Pose2>& poses) {
  const double unit = rec.scene().position_unit;
  for (size_t i = 0; i < poses.size(); ++i) {
    RecordedRobot r = rec.Robot(frame, i);
    EXPECT_NEAR(r.x, poses[i].x, unit / 2 + 1e-9) << "robot " << i << " frame " << frame;
    EXPECT_NEAR(r.y, poses[i].y, unit / 2 + 1e-9) << "robot " << i << " frame " << frame;
    EXPECT_LE(AngleDiff(r.yaw, poses[i].yaw), kPi / 65536 + 1e-9) << "robot " << i << " frame " << frame;
  }
}

TEST(Recording, PosesMatchTheRunWithinTheQuantisation) {
  TempDir d;
  Scene s = ThreeRobots(d, 100);
  ASSERT_TRUE(s.ok()) << s.error;
  const std::string path = d.path() + "/recording.bin";
  Trace trace = RecordRun(*s.world, path, 1, 40);

  Recording rec;
  std::string error;
  ASSERT_TRUE(Recording::Read(path, &rec, &error)) << error;
  EXPECT_DOUBLE_EQ(rec.scene().position_unit, 0.001);  // 10 m arena: millimetres
  ASSERT_EQ(rec.RobotCount(), 3u);
  EXPECT_EQ(rec.scene().robot_ids, (std::vector<std::string>{"a", "b", "c"}));
  ASSERT_EQ(rec.FrameCount(), 41u);  // tick 0 and ticks 1..40
  for (size_t k = 0; k < rec.FrameCount(); ++k) {
    ASSERT_EQ(rec.Tick(k), trace.ticks[k]);
    ExpectFrameMatches(rec, k, trace.poses[k]);
  }
  // The robots did move (the comparison is not between two still scenes).
  for (size_t i = 0; i < 2; ++i)
    EXPECT_GT(std::hypot(rec.Robot(40, i).x - rec.Robot(0, i).x, rec.Robot(40, i).y - rec.Robot(0, i).y), 0.15);
  // A few bytes per robot per tick: 10, plus 4 per frame for the tick.
  EXPECT_EQ(rec.FrameBytes(), 4u + 3 * 10u);
  EXPECT_EQ(rec.scene().ticks_per_second, 10u);
  EXPECT_EQ(rec.scene().length_ticks, 100u);
}

TEST(Recording, EveryNKeepsMultiplesOfNAndTheLastTick) {
  TempDir d;
  Scene s = ThreeRobots(d, 100);
  ASSERT_TRUE(s.ok()) << s.error;
  const std::string path = d.path() + "/recording.bin";
  Trace trace = RecordRun(*s.world, path, 5, 23);

  Recording rec;
  std::string error;
  ASSERT_TRUE(Recording::Read(path, &rec, &error)) << error;
  EXPECT_EQ(rec.scene().every, 5u);
  std::vector<uint64_t> ticks;
  for (size_t k = 0; k < rec.FrameCount(); ++k) ticks.push_back(rec.Tick(k));
  EXPECT_EQ(ticks, (std::vector<uint64_t>{0, 5, 10, 15, 20, 23}));
  for (size_t k = 0; k < rec.FrameCount(); ++k) ExpectFrameMatches(rec, k, trace.poses[ticks[k]]);
  EXPECT_EQ(rec.FrameAtOrBefore(0), 0u);
  EXPECT_EQ(rec.FrameAtOrBefore(9), 1u);
  EXPECT_EQ(rec.FrameAtOrBefore(10), 2u);
  EXPECT_EQ(rec.FrameAtOrBefore(1000), 5u);
}

TEST(Recording, DeadFlagBatteryAndLedColour) {
  TempDir d;
  // The loop functions kill robot b and drain robot c at tick 5.
  d.Write("lf.lua",
          "function post_step()\n"
          "  if experiment.tick == 5 then\n"
          "    experiment.robots[2]:kill()\n"
          "    experiment.robots[3]:set_battery(0.25)\n"
          "  end\n"
          "end\n");
  std::string arena = FootBot("a", -1, -1, 0, "p") + FootBot("b", 1, 0.5, 90, "p") + FootBot("c", 0, 2, 200, "p");
  Scene s = Load(d, Experiment(arena, kPlainController, 100, 1, "<loop_functions script=\"lf.lua\"/>\n"));
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  RecordingWriter writer;
  std::string error;
  const std::string path = d.path() + "/recording.bin";
  ASSERT_TRUE(writer.Open(path, w, 1, &error)) << error;
  for (int t = 0; t < 10; ++t) {
    if (t == 3) {  // applied LED colours, as the LED actuator leaves them: first non-black wins
      w.robots[0].leds[2] = Color{0, 0, 0, 255};
      w.robots[0].leds[4] = Color{255, 0, 0, 255};
      w.robots[0].leds[7] = Color{0, 0, 255, 255};
    }
    Step(w);
    writer.Record(w);
  }
  ASSERT_TRUE(writer.Finish(w, &error)) << error;

  Recording rec;
  ASSERT_TRUE(Recording::Read(path, &rec, &error)) << error;
  ASSERT_EQ(rec.FrameCount(), 11u);
  for (size_t k = 0; k < rec.FrameCount(); ++k) {
    SCOPED_TRACE("tick " + std::to_string(rec.Tick(k)));
    bool killed = rec.Tick(k) >= 5;
    EXPECT_TRUE(rec.Robot(k, 0).alive);
    EXPECT_EQ(rec.Robot(k, 1).alive, !killed);
    EXPECT_TRUE(rec.Robot(k, 2).alive);
    EXPECT_TRUE(rec.Robot(k, 1).controller_ok);
    EXPECT_DOUBLE_EQ(rec.Robot(k, 0).battery, 1.0);
    EXPECT_NEAR(rec.Robot(k, 2).battery, killed ? 0.25 : 1.0, 0.5 / 255 + 1e-12);
    Color c = rec.Robot(k, 0).color;
    if (rec.Tick(k) >= 4)
      EXPECT_TRUE(c == (Color{255, 0, 0, 255}));
    else
      EXPECT_TRUE(c.IsBlack());
    EXPECT_TRUE(rec.Robot(k, 1).color.IsBlack());
  }
}

TEST(Recording, RobotsAddedDuringTheRunAreAbsentBeforeTheirArrival) {
  TempDir d;
  // Two foot-bots join in post_step of tick 7 (between the frames of ticks 5 and 10), one
  // more at tick 21 (after the last multiple of 5, before the last frame, tick 23).
  d.Write("lf.lua",
          "function post_step()\n"
          "  local t = experiment.tick\n"
          "  if t == 7 then\n"
          "    experiment.add_entity('foot-bot', {id = 'd', controller = 'p', position = {-2, 1}})\n"
          "    experiment.add_entity('foot-bot', {id = 'e', controller = 'p', position = {-2, 2}, orientation = 45})\n"
          "  end\n"
          "  if t == 21 then experiment.add_entity('foot-bot', {id = 'f', controller = 'p', position = {3, 3}}) end\n"
          "end\n");
  std::string arena = FootBot("a", -1, -1, 0, "p") + FootBot("b", 1, 0.5, 90, "p") + FootBot("c", 0, 2, 200, "p");
  Scene s = Load(d, Experiment(arena, kPlainController, 100, 1, "<loop_functions script=\"lf.lua\"/>\n"));
  ASSERT_TRUE(s.ok()) << s.error;
  Wheels(s.world->robots[0], 0.10, 0.15);
  const std::string path = d.path() + "/recording.bin";
  Trace trace = RecordRun(*s.world, path, 5, 23);
  ASSERT_EQ(s.world->robots.size(), 6u);

  Recording rec;
  std::string error;
  ASSERT_TRUE(Recording::Read(path, &rec, &error)) << error;
  EXPECT_EQ(rec.scene().robot_ids, (std::vector<std::string>{"a", "b", "c", "d", "e", "f"}));
  EXPECT_EQ(rec.FrameBytes(), 4u + 6 * 10u);
  ASSERT_EQ(rec.FrameCount(), 6u);  // ticks 0, 5, 10, 15, 20, 23
  for (size_t k = 0; k < rec.FrameCount(); ++k) {
    const uint64_t tick = rec.Tick(k);
    SCOPED_TRACE("tick " + std::to_string(tick));
    const std::vector<Pose2>& poses = trace.poses[tick];
    ASSERT_EQ(poses.size(), tick < 7 ? 3u : tick < 21 ? 5u : 6u);
    ExpectFrameMatches(rec, k, poses);  // those present, where the physics had them
    for (size_t i = 0; i < 6; ++i) EXPECT_EQ(rec.Robot(k, i).present, i < poses.size()) << "robot " << i;
  }
  const RecordedRobot absent = rec.Robot(1, 3);
  EXPECT_FALSE(absent.alive);
  EXPECT_EQ(absent.x, 0.0);
  EXPECT_NEAR(rec.Robot(2, 4).yaw, DegToRad(45), 1e-4);
  EXPECT_NEAR(rec.Robot(5, 5).x, 3, 1e-3);
  EXPECT_TRUE(rec.Robot(5, 5).alive);
}

TEST(Recording, SceneMovableObstaclesAndFloor) {
  TempDir d;
  // A floor from the loop functions: 10 m at 100 px/m = 1000 px, stored at 512.
  d.Write("lf.lua", "function floor_color(x, y) if x < 0 and y < 0 then return 0, 0, 0 end return 255, 255, 255 end\n");
  std::string arena =
      "<floor id=\"f\" source=\"loop_functions\" pixels_per_meter=\"100\"/>"
      "<box id=\"wall\" size=\"0.1,4,0.5\" movable=\"false\"><body position=\"3,0,0\" orientation=\"0,0,0\"/></box>"
      "<cylinder id=\"post\" radius=\"0.2\" height=\"0.3\" movable=\"false\"><body position=\"-2,2,0\" "
      "orientation=\"0,0,0\"/></cylinder>"
      "<box id=\"crate\" size=\"0.2,0.2,0.2\" movable=\"true\" mass=\"0.1\"><body position=\"0.4,0,0\" "
      "orientation=\"30,0,0\"/></box>" +
      FootBot("pusher", 0, 0, 0, "p");
  Scene s = Load(d, Experiment(arena, kPlainController, 100, 1, "<loop_functions script=\"lf.lua\"/>\n"));
  ASSERT_TRUE(s.ok()) << s.error;
  World& w = *s.world;
  Wheels(w.robots[0], 0.2, 0.2);
  const std::string path = d.path() + "/recording.bin";
  RecordingWriter writer;
  std::string error;
  ASSERT_TRUE(writer.Open(path, w, 1, &error)) << error;
  std::vector<Pose2> crate;
  crate.push_back(w.physics.ObstaclePose(2));
  for (int t = 0; t < 30; ++t) {
    Step(w);
    writer.Record(w);
    crate.push_back(w.physics.ObstaclePose(2));
  }
  ASSERT_TRUE(writer.Finish(w, &error)) << error;

  Recording rec;
  ASSERT_TRUE(Recording::Read(path, &rec, &error)) << error;
  const RecordingScene& sc = rec.scene();
  EXPECT_EQ(sc.arena_min, Vec2(-5, -5));
  EXPECT_EQ(sc.arena_size, Vec2(10, 10));
  ASSERT_EQ(sc.obstacles.size(), 3u);
  EXPECT_EQ(sc.obstacles[0].id, "wall");
  EXPECT_FALSE(sc.obstacles[0].cylinder);
  EXPECT_FALSE(sc.obstacles[0].movable);
  EXPECT_FLOAT_EQ(sc.obstacles[0].size_y, 4.0f);
  EXPECT_TRUE(sc.obstacles[1].cylinder);
  EXPECT_FLOAT_EQ(sc.obstacles[1].radius, 0.2f);
  EXPECT_FLOAT_EQ(sc.obstacles[1].pose.y, 2.0f);
  EXPECT_TRUE(sc.obstacles[2].movable);
  EXPECT_NEAR(sc.obstacles[2].pose.yaw, DegToRad(30), 1e-6);
  ASSERT_EQ(sc.movable, std::vector<int>{2});
  for (size_t k = 0; k < rec.FrameCount(); ++k) {
    Pose2 p = rec.Movable(k, 0);
    EXPECT_NEAR(p.x, crate[k].x, 0.0005 + 1e-9);
    EXPECT_NEAR(p.y, crate[k].y, 0.0005 + 1e-9);
    EXPECT_LE(AngleDiff(p.yaw, crate[k].yaw), kPi / 65536 + 1e-9);
  }
  EXPECT_GT(rec.Movable(30, 0).x - rec.Movable(0, 0).x, 0.05) << "the robot pushed the crate";
  EXPECT_EQ(sc.floor_width, 512);
  EXPECT_EQ(sc.floor_height, 512);
  ASSERT_GT(sc.floor_png.size(), 8u);
  EXPECT_EQ(sc.floor_png.substr(1, 3), "PNG");
  EXPECT_EQ(rec.FrameBytes(), 4u + 10u + 8u);
}

TEST(Recording, TheFileAppearsOnlyWhenFinished) {
  TempDir d;
  Scene s = ThreeRobots(d, 100);
  ASSERT_TRUE(s.ok()) << s.error;
  const std::string path = d.path() + "/recording.bin";
  std::string error;
  {
    RecordingWriter writer;
    ASSERT_TRUE(writer.Open(path, *s.world, 1, &error)) << error;
    Step(*s.world);
    writer.Record(*s.world);
    EXPECT_FALSE(FileExists(path));
  }  // abandoned: nothing left behind
  EXPECT_FALSE(FileExists(path));
  EXPECT_EQ(std::system(("test -z \"$(ls -A '" + d.path() + "' | grep tmp)\"").c_str()), 0) << "temporary file left";

  RecordingWriter writer;
  ASSERT_TRUE(writer.Open(path, *s.world, 1, &error)) << error;
  ASSERT_TRUE(writer.Finish(*s.world, &error)) << error;
  EXPECT_TRUE(FileExists(path));
  EXPECT_EQ(writer.FramesWritten(), 1u);
}

TEST(Recording, ReaderRejectsOtherFilesAndIgnoresACutFrame) {
  TempDir d;
  Scene s = ThreeRobots(d, 100);
  ASSERT_TRUE(s.ok()) << s.error;
  const std::string path = d.path() + "/recording.bin";
  RecordRun(*s.world, path, 1, 5);
  std::string bytes, error;
  ASSERT_TRUE(ReadFile(path, &bytes));
  Recording rec;
  EXPECT_FALSE(Recording::Parse("<html>not a recording</html>", &rec, &error));
  EXPECT_NE(error.find("not an essaim recording"), std::string::npos) << error;
  EXPECT_FALSE(Recording::Parse(bytes.substr(0, 40), &rec, &error));
  // A file cut in the middle of its last frame: the complete frames remain readable.
  ASSERT_TRUE(Recording::Parse(bytes.substr(0, bytes.size() - 7), &rec, &error)) << error;
  EXPECT_EQ(rec.FrameCount(), 5u);
}

// The streaming reader (essaim video) gives the frames the whole-file reader gives, reading
// one frame at a time; it finds frames by tick and refuses what the other refuses.
TEST(Recording, StreamReadsTheSameFramesOneAtATime) {
  TempDir d;
  Scene s = ThreeRobots(d, 100);
  ASSERT_TRUE(s.ok()) << s.error;
  const std::string path = d.path() + "/recording.bin";
  RecordRun(*s.world, path, 4, 30);  // ticks 0, 4, ..., 28 and the last, 30
  Recording whole;
  RecordingStream stream;
  std::string error;
  ASSERT_TRUE(Recording::Read(path, &whole, &error)) << error;
  ASSERT_TRUE(stream.Open(path, &error)) << error;
  ASSERT_EQ(stream.FrameCount(), whole.FrameCount());
  EXPECT_EQ(stream.scene().robot_ids, whole.scene().robot_ids);
  EXPECT_EQ(stream.scene().every, 4u);
  std::vector<uint8_t> bytes;
  for (size_t k = 0; k < whole.FrameCount(); ++k) {
    ASSERT_TRUE(stream.ReadFrame(k, &bytes, &error)) << error;
    ASSERT_EQ(bytes.size(), whole.FrameBytes());
    FrameView f(&stream.scene(), bytes.data());
    EXPECT_EQ(f.Tick(), whole.Tick(k));
    EXPECT_EQ(stream.TickOf(k), whole.Tick(k));
    for (size_t i = 0; i < whole.RobotCount(); ++i) {
      EXPECT_EQ(f.Robot(i).x, whole.Robot(k, i).x);
      EXPECT_EQ(f.Robot(i).yaw, whole.Robot(k, i).yaw);
    }
  }
  EXPECT_EQ(whole.Tick(whole.FrameCount() - 1), 30u);
  for (uint64_t tick : {0, 3, 4, 29, 30, 1000}) EXPECT_EQ(stream.FrameAtOrBefore(tick), whole.FrameAtOrBefore(tick));
  EXPECT_FALSE(stream.ReadFrame(whole.FrameCount(), &bytes, &error));
  EXPECT_NE(error.find("cannot read frame"), std::string::npos) << error;

  std::string file;
  ASSERT_TRUE(ReadFile(path, &file));
  RecordingStream cut;  // a cut last frame
  ASSERT_TRUE(cut.Open(d.Write("cut.bin", file.substr(0, file.size() - 7)), &error)) << error;
  EXPECT_EQ(cut.FrameCount(), whole.FrameCount() - 1);
  RecordingStream other;
  EXPECT_FALSE(other.Open(d.Write("page.html", "<html>not a recording</html>"), &error));
  EXPECT_NE(error.find("not an essaim recording"), std::string::npos) << error;
  RecordingStream short_file;
  EXPECT_FALSE(short_file.Open(d.Write("short.bin", "ESSAIM"), &error));
  EXPECT_NE(error.find("not an essaim recording"), std::string::npos) << error;
  RecordingStream missing;
  EXPECT_FALSE(missing.Open(d.path() + "/missing.bin", &error));
  EXPECT_NE(error.find("cannot read"), std::string::npos) << error;
}

TEST(Recording, Rgb565RoundTripsPrimaries) {
  for (Color c : {Color{255, 0, 0, 255}, Color{0, 255, 0, 255}, Color{0, 0, 255, 255}, Color{255, 255, 0, 255},
                  Color{255, 255, 255, 255}, Color{0, 0, 0, 255}})
    EXPECT_TRUE(UnpackRgb565(PackRgb565(c)) == c);
  Color orange = UnpackRgb565(PackRgb565(Color{255, 140, 0, 255}));
  EXPECT_NEAR(orange.g, 140, 4);
}

}  // namespace
}  // namespace essaim
