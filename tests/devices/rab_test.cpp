// Range-and-bearing and LED/camera experiments end to end (issue "Every foot-bot sensor
// and actuator"): a message relayed over three robots, one tick per hop; a controller that
// lights its LEDs and a camera robot that reads the colour.
#include <gtest/gtest.h>

#include "devices/media.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

std::string Bot(const std::string& id, double x, double y, const std::string& ctrl, const std::string& attrs = "") {
  char buf[320];
  std::snprintf(
      buf, sizeof buf,
      "<foot-bot id=\"%s\" %s><body position=\"%g,%g,0\" orientation=\"0,0,0\"/><controller config=\"%s\"/></foot-bot>",
      id.c_str(), attrs.c_str(), x, y, ctrl.c_str());
  return buf;
}

std::string Controller(const std::string& id, const std::string& script) {
  return "<lua_controller id=\"" + id +
         "\"><actuators>"
         "<differential_steering implementation=\"default\"/>"
         "<leds implementation=\"default\" medium=\"leds\"/>"
         "<range_and_bearing implementation=\"default\"/>"
         "</actuators><sensors>"
         "<colored_blob_omnidirectional_camera implementation=\"rot_z_only\" medium=\"leds\" show_rays=\"false\"/>"
         "<range_and_bearing implementation=\"medium\" medium=\"rab\" show_rays=\"false\"/>"
         "</sensors><params script=\"" +
         script + "\"/></lua_controller>";
}

std::string Media(std::string xml) {
  xml.replace(xml.find("<media/>"), 8,
              "<media><range_and_bearing id=\"rab\" check_occlusions=\"true\"/><led id=\"leds\"/></media>");
  return xml;
}

struct Run {
  std::vector<std::string> lines;
  Scene s;
};

std::unique_ptr<Run> Start(const TempDir& d, const std::string& xml) {
  auto r = std::make_unique<Run>();
  SimOptions sim;
  Run* raw = r.get();
  sim.log_sink = [raw](char, const std::string& line, const LogOrigin&) { raw->lines.push_back(line); };
  r->s = Load(d, xml, {}, sim);
  return r;
}

TEST(RabIntegration, MessageRelayedOverThreeRobots) {
  TempDir d;
  // A writes 42 at its step 1. Every robot repeats the largest byte it hears; each logs
  // the step at which it first holds 42. Ranges of 1 m, robots 0.8 m apart in a row:
  // C (1.6 m from A) can only learn it through B. B shields nothing here: the robots are
  // offset sideways so that A-C is not blocked by B's body, to prove range alone stops it.
  d.Write("relay.lua", R"(
n = 0
have = 0
function init() end
function step()
  n = n + 1
  if robot.id == "A" and n == 1 then have = 42 end
  for i = 1, #robot.range_and_bearing do
    local b = robot.range_and_bearing[i].data[1]
    if b > have then have = b end
  end
  if have == 42 and not told then told = true; print(robot.id, "has it at step", n) end
  robot.range_and_bearing.set_data(1, have)
end
)");
  auto run = Start(
      d, Media(Experiment(Bot("A", 0, 0, "relay", "rab_range=\"1\"") + Bot("B", 0.8, 0.3, "relay", "rab_range=\"1\"") +
                              Bot("C", 1.6, 0, "relay", "rab_range=\"1\""),
                          Controller("relay", "relay.lua"), 100)));
  ASSERT_TRUE(run->s.ok()) << run->s.error;
  RunTicks(*run->s.world, 6);
  EXPECT_TRUE(run->s.world->controller_errors.empty());
  EXPECT_EQ(run->lines,
            std::vector<std::string>({"A\thas it at step\t1", "B\thas it at step\t2", "C\thas it at step\t3"}));
  // C never hears A directly.
  for (const RabPacket& p : run->s.world->robots[2].rd.rab) EXPECT_NE(p.sender, 0);
}

TEST(RabIntegration, CameraReadsAnotherRobotsLedColour) {
  TempDir d;
  // The painter turns magenta at step 5; the watcher logs the first step it sees it, with
  // the colour as a string key built from integer components.
  d.Write("paint.lua", R"(
n = 0
function init() end
function step()
  n = n + 1
  if n == 5 then robot.leds.set_all_colors("magenta") end
end
)");
  d.Write("watch.lua", R"(
n = 0
function init() robot.colored_blob_omnidirectional_camera.enable() end
function step()
  n = n + 1
  for i = 1, #robot.colored_blob_omnidirectional_camera do
    local b = robot.colored_blob_omnidirectional_camera[i]
    local key = b.color.red .. "," .. b.color.green .. "," .. b.color.blue
    if not seen and key == "255,0,255" then
      seen = true
      print("magenta at step", n, "angle", string.format("%.3f", b.angle), "blobs", #robot.colored_blob_omnidirectional_camera)
    end
  end
end
)");
  auto run = Start(d, Media(Experiment(Bot("painter", 0.3, 0.3, "paint") + Bot("watcher", 0, 0, "watch"),
                                       Controller("paint", "paint.lua") + Controller("watch", "watch.lua"), 100)));
  ASSERT_TRUE(run->s.ok()) << run->s.error;
  RunTicks(*run->s.world, 8);
  EXPECT_TRUE(run->s.world->controller_errors.empty());
  // Seen one step later. From (0,0), the painter at (0.3, 0.3) shows its ring LEDs 5..11
  // (those facing the watcher; its body hides the rest) and its beacon: 8 blobs, the first
  // one LED 5 at atan2 = 0.9945 rad.
  EXPECT_EQ(run->lines, std::vector<std::string>({"magenta at step\t6\tangle\t0.995\tblobs\t8"}));
}

// Brute force for the crowd tests below, one test per (pair, body): the pair's ray runs
// between the bodies' centres from the lower index, as the media stage casts it, and
// anything entered before `t_b` (where it enters the other body) hides the pair.
using MediaState = decltype(World::media);
struct PairRay {
  int lo, hi;
  Vec2 from, to;
  double t_b;
};
PairRay RayBetween(const MediaState& m, int a, int b) {
  PairRay r{std::min(a, b), std::max(a, b), Vec2::Zero(), Vec2::Zero(), 0};
  r.from = m.body_xy[r.lo];
  r.to = m.body_xy[r.hi];
  const double len = (r.to - r.from).norm();
  // The partner's first shape: its body, or its gripper disc where that faces the device.
  r.t_b = std::min(std::max(0.0, len - footbot::kRadius) / len,
                   CircleEntry(r.from, r.to, m.gripper_xy[r.hi], kGripperRadius));
  return r;
}
bool HiddenByABody(const MediaState& m, const PairRay& r, int robots) {
  for (int c = 0; c < robots; ++c) {
    if (c == r.lo || c == r.hi) continue;
    if (CircleEntry(r.from, r.to, m.body_xy[c], footbot::kRadius) < r.t_b) return true;
    if (CircleEntry(r.from, r.to, m.gripper_xy[c], kGripperRadius) < r.t_b) return true;
  }
  return false;
}
bool HiddenByAnObstacle(const Model& model, const MediaState& m, const PairRay& r) {
  const double z = m.rab_pos[r.lo].z();
  for (size_t k = 0; k < model.obstacles.size(); ++k) {
    const ObstacleDef& o = model.obstacles[k];
    if (z < o.z || z > o.z + o.height) continue;
    const double entry = o.kind == ShapeKind::Cylinder
                             ? CircleEntry(r.from, r.to, m.obstacle_xy[k], o.radius)
                             : BoxEntry(r.from, r.to, m.obstacle_xy[k], m.obstacle_cs[k], o.size_x / 2, o.size_y / 2);
    if (entry < r.t_b) return true;
  }
  return false;
}
/// Every inbox of this tick against the brute force (bodies, then obstacles); counts the
/// messages heard and the in-range pairs that only an obstacle hides.
void ExpectBruteForceInboxes(const World& w, const Model& model, int tick, size_t* heard, size_t* hidden_by_obstacle) {
  const MediaState& m = w.media;
  const int n = static_cast<int>(w.robots.size());
  for (int a = 0; a < n; ++a) {
    std::vector<int> expect;
    for (int b = 0; b < n; ++b) {
      if (b == a) continue;
      if ((m.rab_pos[b] - m.rab_pos[a]).norm() >= model.robots[b].rab_range) continue;
      const PairRay ray = RayBetween(m, a, b);
      if (HiddenByABody(m, ray, n)) continue;
      if (HiddenByAnObstacle(model, m, ray)) {
        ++*hidden_by_obstacle;
        continue;
      }
      expect.push_back(b);
    }
    *heard += expect.size();
    EXPECT_EQ(m.rab_inbox[a], expect) << "robot " << a << " at tick " << tick;
  }
}

// The media stage's occlusion shortcuts (per-device offsets, nearest-first scan with a
// distance cut-off) must decide exactly what one CircleEntry per (pair, body)
// decides: compare every inbox of a dense, moving crowd with that brute force.
TEST(RabIntegration, CrowdInboxesMatchBruteForceOcclusion) {
  TempDir d;
  d.Write("spin.lua", "function init() end function step() robot.wheels.set_velocity(8, 3) end");
  std::string bots;
  for (int i = 0; i < 60; ++i)  // a 10 x 6 lattice, 0.3 m apart, jittered: many occluders
    bots += Bot("b" + std::to_string(i), -1.4 + 0.3 * (i % 10) + 0.01 * (i % 3),
                -0.8 + 0.3 * (i / 10.0) - 0.02 * (i % 4), "spin", "rab_range=\"1.2\"");
  auto run = Start(d, Media(Experiment(bots, Controller("spin", "spin.lua"), 100)));
  ASSERT_TRUE(run->s.ok()) << run->s.error;
  World& w = *run->s.world;
  const auto& m = w.media;
  const int n = static_cast<int>(w.robots.size());
  size_t heard = 0, hidden = 0;
  for (int tick = 0; tick < 5; ++tick) {
    RunTicks(w, 1);
    for (int a = 0; a < n; ++a) {
      std::vector<int> expect;
      for (int b = 0; b < n; ++b) {
        if (b == a) continue;
        if ((m.rab_pos[b] - m.rab_pos[a]).norm() >= run->s.model->robots[b].rab_range) continue;
        const bool blocked = HiddenByABody(m, RayBetween(m, a, b), n);
        if (blocked)
          ++hidden;
        else
          expect.push_back(b);
      }
      heard += expect.size();
      EXPECT_EQ(m.rab_inbox[a], expect) << "robot " << a << " at tick " << tick;
    }
  }
  EXPECT_GT(heard, 500u);  // a real crowd: many partners and many hidden ones
  EXPECT_GT(hidden, 500u);
}

// Obstacles among a crowd: rotated boxes and cylinders tall enough to hide senders. The
// stage skips the exact obstacle test when a pair's segment box misses the obstacle's
// bounding box: the inboxes must equal one CircleEntry/BoxEntry per (pair,
// body or obstacle).
TEST(RabIntegration, CrowdAmongObstaclesMatchesBruteForceOcclusion) {
  TempDir d;
  d.Write("spin.lua", "function init() end function step() robot.wheels.set_velocity(6, 2) end");
  std::string scene;
  for (int i = 0; i < 40; ++i)  // an 8 x 5 lattice, 0.5 m apart, jittered
    scene += Bot("b" + std::to_string(i), -1.9 + 0.5 * (i % 8) + 0.02 * (i % 3), -1.1 + 0.5 * (i / 8) - 0.03 * (i % 4),
                 "spin", "rab_range=\"2.5\"");
  for (int k = 0; k < 6; ++k) {  // between the lattice points
    char buf[320];
    const double x = -1.65 + 0.5 * k, y = k % 2 ? -0.35 : 0.15;  // cell centres
    if (k % 3 == 2)
      std::snprintf(buf, sizeof buf,
                    "<cylinder id=\"o%d\" radius=\"0.06\" height=\"0.5\" movable=\"false\">"
                    "<body position=\"%g,%g,0\" orientation=\"0,0,0\"/></cylinder>",
                    k, x, y);
    else
      std::snprintf(buf, sizeof buf,
                    "<box id=\"o%d\" size=\"0.3,0.05,0.5\" movable=\"false\">"
                    "<body position=\"%g,%g,0\" orientation=\"%d,0,0\"/></box>",
                    k, x, y, 25 + 40 * k);
    scene += buf;
  }
  // Two long, slightly turned walls between rows: segments that cross them away from
  // their centres (the bounding-box shortcut's hard case).
  scene +=
      "<box id=\"w0\" size=\"1.2,0.04,0.5\" movable=\"false\"><body position=\"-0.6,-0.85,0\" "
      "orientation=\"3,0,0\"/></box>"
      "<box id=\"w1\" size=\"1.2,0.04,0.5\" movable=\"false\"><body position=\"0.5,0.65,0\" "
      "orientation=\"-4,0,0\"/></box>";
  auto run = Start(d, Media(Experiment(scene, Controller("spin", "spin.lua"), 100)));
  ASSERT_TRUE(run->s.ok()) << run->s.error;
  World& w = *run->s.world;
  size_t heard = 0, hidden_by_obstacle = 0;
  for (int tick = 0; tick < 5; ++tick) {
    RunTicks(w, 1);
    ExpectBruteForceInboxes(w, *run->s.model, tick, &heard, &hidden_by_obstacle);
  }
  EXPECT_GT(heard, 300u);
  EXPECT_GT(hidden_by_obstacle, 50u);  // the obstacles do hide some pairs
}

// Long ranges across the whole arena, up to its border: each pair's segment visits the
// cells of the obstacle grid it crosses, row by row. Every cell it touches must
// be visited, at any slope and at the grid's edge rows and columns, for the inboxes to
// equal one CircleEntry/BoxEntry per (pair, body or obstacle).
TEST(RabIntegration, LongRangesAcrossScatteredObstaclesMatchBruteForceOcclusion) {
  TempDir d;
  d.Write("spin.lua", "function init() end function step() robot.wheels.set_velocity(5, -4) end");
  std::string scene;
  for (int i = 0; i < 100; ++i)  // a 10 x 10 lattice, 0.96 m apart, to 0.2 m from the walls' edge
    scene += Bot("b" + std::to_string(i), -4.8 + 0.96 * (i % 10) + 0.03 * (i % 3),
                 -4.8 + 0.96 * (i / 10) - 0.02 * (i % 4), "spin", "rab_range=\"6\"");
  char buf[320];
  for (int k = 0; k < 45; ++k) {  // small cylinders at the centres of the lattice's even rows
    const double x = -4.32 + 0.96 * (k % 9), y = -4.32 + 1.92 * (k / 9);
    std::snprintf(buf, sizeof buf,
                  "<cylinder id=\"c%d\" radius=\"0.05\" height=\"0.5\" movable=\"false\">"
                  "<body position=\"%g,%g,0\" orientation=\"0,0,0\"/></cylinder>",
                  k, x + 0.1 * (k % 3), y);
    scene += buf;
  }
  for (int k = 0; k < 5; ++k) {  // long, slightly turned walls along the odd rows' centres
    std::snprintf(buf, sizeof buf,
                  "<box id=\"w%d\" size=\"2.6,0.04,0.5\" movable=\"false\">"
                  "<body position=\"%g,%g,0\" orientation=\"%d,0,0\"/></box>",
                  k, -3 + 1.5 * k, -3.36 + 1.92 * k, 4 - 2 * k);
    scene += buf;
  }
  auto run = Start(d, Media(Experiment(scene, Controller("spin", "spin.lua"), 100)));
  ASSERT_TRUE(run->s.ok()) << run->s.error;
  World& w = *run->s.world;
  size_t heard = 0, hidden_by_obstacle = 0;
  for (int tick = 0; tick < 3; ++tick) {
    RunTicks(w, 1);
    ExpectBruteForceInboxes(w, *run->s.model, tick, &heard, &hidden_by_obstacle);
  }
  EXPECT_GT(heard, 1000u);
  EXPECT_GT(hidden_by_obstacle, 1000u);
}

// The media stage routes devices on several threads: a dense crowd that steers
// by what it hears must get the same inboxes, message by message and tick by tick, with
// 1, 2 and 3 threads (and so the same poses).
TEST(RabIntegration, CrowdInboxesDoNotDependOnThreads) {
  TempDir d;
  d.Write("chat.lua", R"(
function init() end
function step()
  local n, sum = #robot.range_and_bearing, 0
  for i = 1, n do sum = sum + robot.range_and_bearing[i].data[1] end
  robot.range_and_bearing.set_data(1, (sum + n) % 256)
  robot.wheels.set_velocity(4 + n % 7, 4 + sum % 5)
end
)");
  std::string bots;
  for (int i = 0; i < 240; ++i)  // a 20 x 12 lattice, 0.35 m apart, jittered
    bots += Bot("c" + std::to_string(i), -3.3 + 0.35 * (i % 20) + 0.013 * (i % 7),
                -2 + 0.35 * (i / 20) - 0.011 * (i % 5), "chat", "rab_range=\"2\"");
  const std::string xml = Media(Experiment(bots, Controller("chat", "chat.lua"), 100));
  std::vector<std::vector<std::vector<int>>> inboxes[3];  // [threads - 1][tick][robot]
  std::vector<Vec2> poses[3];
  for (int k = 0; k < 3; ++k) {
    SimOptions sim;
    sim.threads = k + 1;
    Scene s = Load(d, xml, {}, sim);
    ASSERT_TRUE(s.ok()) << s.error;
    for (int tick = 0; tick < 8; ++tick) {
      RunTicks(*s.world, 1);
      inboxes[k].push_back(s.world->media.rab_inbox);
    }
    EXPECT_TRUE(s.world->controller_errors.empty());
    poses[k] = s.world->media.body_xy;
  }
  size_t heard = 0;
  for (const auto& tick : inboxes[0])
    for (const auto& inbox : tick) heard += inbox.size();
  EXPECT_GT(heard, 8u * 240 * 10);  // a real crowd: ten or more partners each on average
  for (int k = 1; k < 3; ++k) {
    for (size_t tick = 0; tick < inboxes[0].size(); ++tick)
      for (size_t r = 0; r < inboxes[0][tick].size(); ++r)
        ASSERT_EQ(inboxes[k][tick][r], inboxes[0][tick][r]) << (k + 1) << " threads, tick " << tick << ", robot " << r;
    for (size_t r = 0; r < poses[0].size(); ++r) {  // bit for bit
      EXPECT_EQ(poses[k][r].x(), poses[0][r].x()) << (k + 1) << " threads, robot " << r;
      EXPECT_EQ(poses[k][r].y(), poses[0][r].y()) << (k + 1) << " threads, robot " << r;
    }
  }
}

}  // namespace
}  // namespace essaim
