// The live view's pieces without a browser: access checks (token, Host, Origin), control
// commands, frame encoding and the latest-frame mailbox, the file watcher, and the live
// experiment's reload (errors keep the last good world).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <thread>

#include "core/json.h"
#include "serve/access.h"
#include "serve/control.h"
#include "serve/file_watcher.h"
#include "serve/frame_mailbox.h"
#include "serve/live_experiment.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

AccessPolicy Policy() { return {"0123456789abcdef0123456789abcdef", OwnHosts("127.0.0.1", 8765)}; }

TEST(ServeAccess, TokensAreFreshHex) {
  std::string a = NewToken(), b = NewToken();
  EXPECT_EQ(a.size(), 32u);
  EXPECT_EQ(a.find_first_not_of("0123456789abcdef"), std::string::npos);
  EXPECT_NE(a, b);
}

TEST(ServeAccess, TokenIsNeededAndMustMatch) {
  const AccessPolicy p = Policy();
  std::string why;
  EXPECT_EQ(CheckAccess(p, "127.0.0.1:8765", "", "", "", &why), 401);
  EXPECT_NE(why.find("token"), std::string::npos);
  EXPECT_EQ(CheckAccess(p, "127.0.0.1:8765", "", "wrong", "", &why), 403);
  EXPECT_EQ(CheckAccess(p, "127.0.0.1:8765", "", p.token + "0", "", &why), 403);
  EXPECT_EQ(CheckAccess(p, "127.0.0.1:8765", "", "", "Bearer nope", &why), 403);
  EXPECT_EQ(CheckAccess(p, "127.0.0.1:8765", "", p.token, "", &why), 0);
  EXPECT_EQ(CheckAccess(p, "localhost:8765", "", "", "Bearer " + p.token, &why), 0);
  EXPECT_EQ(CheckAccess(p, "127.0.0.1:8765", "", "", "Basic " + p.token, &why), 401);
}

TEST(ServeAccess, ForeignHostOrOriginIsRefusedEvenWithTheToken) {
  const AccessPolicy p = Policy();
  std::string why;
  // DNS rebinding: a name that resolves to 127.0.0.1 but is not this server's.
  EXPECT_EQ(CheckAccess(p, "evil.example:8765", "", p.token, "", &why), 403);
  EXPECT_NE(why.find("Host"), std::string::npos);
  EXPECT_EQ(CheckAccess(p, "127.0.0.1:9999", "", p.token, "", &why), 403);
  EXPECT_EQ(CheckAccess(p, "", "", p.token, "", &why), 403);
  // CSRF: a page elsewhere posting to the server.
  EXPECT_EQ(CheckAccess(p, "127.0.0.1:8765", "http://evil.example", p.token, "", &why), 403);
  EXPECT_NE(why.find("Origin"), std::string::npos);
  EXPECT_EQ(CheckAccess(p, "127.0.0.1:8765", "null", p.token, "", &why), 403);
  EXPECT_EQ(CheckAccess(p, "127.0.0.1:8765", "https://127.0.0.1:8765", p.token, "", &why), 403);
  EXPECT_EQ(CheckAccess(p, "127.0.0.1:8765", "http://127.0.0.1:8765", p.token, "", &why), 0);
  EXPECT_EQ(CheckAccess(p, "127.0.0.1:8765", "http://localhost:8765", p.token, "", &why), 0);
}

TEST(ServeAccess, AnotherBoundAddressIsItsOwnHost) {
  std::vector<std::string> hosts = OwnHosts("192.168.1.5", 80);
  EXPECT_NE(std::find(hosts.begin(), hosts.end(), "192.168.1.5:80"), hosts.end());
  EXPECT_NE(std::find(hosts.begin(), hosts.end(), "127.0.0.1:80"), hosts.end());
}

TEST(ServeAccess, EveryAddressAcceptsIpAddressesButNotNames) {
  AccessPolicy p = PolicyFor("0123456789abcdef", "0.0.0.0", 8765);
  std::string why;
  EXPECT_EQ(CheckAccess(p, "10.1.2.3:8765", "http://10.1.2.3:8765", p.token, "", &why), 0);
  EXPECT_EQ(CheckAccess(p, "[fe80::1]:8765", "", p.token, "", &why), 0);
  EXPECT_EQ(CheckAccess(p, "10.1.2.3:8766", "", p.token, "", &why), 403);
  EXPECT_EQ(CheckAccess(p, "rebind.example:8765", "", p.token, "", &why), 403);
  EXPECT_EQ(CheckAccess(p, "1.2.3.example:8765", "", p.token, "", &why), 403);
  AccessPolicy local = PolicyFor("0123456789abcdef", "127.0.0.1", 8765);
  EXPECT_EQ(CheckAccess(local, "10.1.2.3:8765", "", local.token, "", &why), 403);
}

TEST(ServeControl, CommandsAndTheirErrors) {
  ControlCommand c;
  std::string error;
  ASSERT_TRUE(ParseControl(R"({"cmd": "play"})", &c, &error));
  EXPECT_EQ(c.kind, ControlKind::Play);
  ASSERT_TRUE(ParseControl(R"({"cmd": "run", "ticks": 250})", &c, &error));
  EXPECT_EQ(c.kind, ControlKind::Step);
  EXPECT_EQ(c.ticks, 250u);
  ASSERT_TRUE(ParseControl(R"({"cmd": "step"})", &c, &error));
  EXPECT_EQ(c.ticks, 1u);
  ASSERT_TRUE(ParseControl(R"({"cmd": "speed", "value": 0})", &c, &error));
  EXPECT_EQ(c.speed, 0);
  ASSERT_TRUE(ParseControl(R"({"cmd": "reset", "seed": 42})", &c, &error));
  EXPECT_EQ(c.seed.value_or(0), 42u);
  ASSERT_TRUE(ParseControl(R"({"cmd": "reset", "new_seed": true})", &c, &error));
  EXPECT_TRUE(c.new_seed);

  EXPECT_FALSE(ParseControl("{not json", &c, &error));
  EXPECT_NE(error.find("invalid JSON"), std::string::npos);
  EXPECT_FALSE(ParseControl(R"(["play"])", &c, &error));
  EXPECT_FALSE(ParseControl(R"({"cmd": "jump"})", &c, &error));
  EXPECT_NE(error.find("unknown cmd 'jump'"), std::string::npos);
  EXPECT_FALSE(ParseControl(R"({"cmd": "step", "ticks": 0})", &c, &error));
  EXPECT_FALSE(ParseControl(R"({"cmd": "step", "ticks": "5"})", &c, &error));
  EXPECT_FALSE(ParseControl(R"({"cmd": "speed", "value": -1})", &c, &error));
  EXPECT_FALSE(ParseControl(R"({"cmd": "speed"})", &c, &error));
  EXPECT_FALSE(ParseControl(R"({"cmd": "reset", "seed": -3})", &c, &error));
  EXPECT_FALSE(ParseIndex("-1"));
  EXPECT_FALSE(ParseIndex("x"));
  EXPECT_EQ(ParseIndex("12").value_or(-1), 12);
}

TEST(ServeFrames, SseEventsCarryEachLineAsData) {
  EXPECT_EQ(SseEvent("frame", R"({"tick":3})"), "event: frame\ndata: {\"tick\":3}\n\n");
  EXPECT_EQ(SseEvent("x", "a\nb"), "event: x\ndata: a\ndata: b\n\n");
}

TEST(ServeFrames, TheLatestFrameWinsAndCloseWakesWaiters) {
  FrameMailbox box;
  uint64_t seq = 0;
  FrameMailbox::Frame f;
  EXPECT_FALSE(box.WaitNewer(&seq, &f, std::chrono::milliseconds(1)));
  box.Publish("one");
  box.Publish("two");
  box.Publish("three");  // a slow reader sees only the last
  ASSERT_TRUE(box.WaitNewer(&seq, &f, std::chrono::milliseconds(1)));
  EXPECT_EQ(*f, "three");
  EXPECT_EQ(seq, 3u);
  EXPECT_FALSE(box.WaitNewer(&seq, &f, std::chrono::milliseconds(1)));  // nothing newer
  std::thread reader([&] { EXPECT_FALSE(box.WaitNewer(&seq, &f, std::chrono::hours(1))); });
  box.Close();
  reader.join();
}

const char* kCtrl = R"(
count = 0
state = {name = "explore", target = {x = 1.5, y = -2}}
function init() robot.leds.set_all_colors("red") end
function step()
  count = count + 1
  robot.wheels.set_velocity(5, 5)
  if count == 2 then log("two steps") end
end
)";

std::string TwoRobots() {
  std::string ctrl =
      "<lua_controller id=\"c\"><actuators><differential_steering implementation=\"default\"/>"
      "<leds implementation=\"default\" medium=\"leds\"/></actuators><sensors>"
      "<positioning implementation=\"default\"/></sensors><params script=\"ctrl.lua\"/></lua_controller>";
  std::string xml = Experiment(FootBot("fb0", 1, 2, 90, "c") + FootBot("fb1", -1, 0, 0, "c"), ctrl, 100);
  xml.replace(xml.find("<media/>"), 8, "<media><led id=\"leds\"/></media>");
  return xml;
}

TEST(ServeFrames, FrameJsonHasTheRobotsAndTheRunState) {
  TempDir d;
  d.Write("ctrl.lua", kCtrl);
  Scene s = Load(d, TwoRobots());
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 3);
  FrameInfo info;
  info.run = 4;
  info.paused = false;
  info.error = "x.lua:3: oops";
  std::string line = FrameText(*s.world, info);
  EXPECT_EQ(line.find('\n'), std::string::npos);  // one SSE data: line
  Json f;
  std::string error;
  ASSERT_TRUE(ParseJson(line, &f, &error)) << error;
  EXPECT_EQ(f["tick"], 3);
  EXPECT_EQ(f["run"], 4);
  EXPECT_EQ(f["paused"], false);
  EXPECT_EQ(f["error"], "x.lua:3: oops");
  ASSERT_EQ(f["robots"].size(), 2u);
  const Json& r0 = f["robots"][0];
  EXPECT_EQ(r0["id"], "fb0");
  Pose2 pose = s.world->physics.RobotPose(0);
  EXPECT_NEAR(r0["x"].get<double>(), pose.x, 1e-4);
  EXPECT_NEAR(r0["y"].get<double>(), pose.y, 1e-4);
  EXPECT_GT(r0["y"].get<double>(), 2.0);  // drove north
  EXPECT_EQ(r0["led"], Json::array({255, 0, 0}));
  EXPECT_EQ(r0["alive"], true);
  Json scene;
  ASSERT_TRUE(ParseJson(SceneText(*s.world), &scene, &error)) << error;
  EXPECT_EQ(scene["ids"], Json::array({"fb0", "fb1"}));
  EXPECT_EQ(scene["sizeX"], 10);
}

TEST(ServeFileWatcher, SavesInPlaceByRenameAndRecreationAreSeen) {
  TempDir d;
  std::string watched = d.Write("ctrl.lua", "-- one"), other = d.Write("other.lua", "");
  FileWatcher w;
  ASSERT_TRUE(w.Ok()) << w.Error();
  w.Watch({watched});
  ASSERT_TRUE(w.Error().empty()) << w.Error();
  EXPECT_FALSE(w.WaitForChange(50));
  // Another file of the folder is no change.
  {
    FILE* f = std::fopen(other.c_str(), "w");
    std::fputs("x", f);
    std::fclose(f);
  }
  EXPECT_FALSE(w.WaitForChange(100));
  // In place.
  {
    FILE* f = std::fopen(watched.c_str(), "w");
    std::fputs("-- two", f);
    std::fclose(f);
  }
  std::vector<std::string> changed;
  ASSERT_TRUE(w.WaitForChange(5000, &changed));
  EXPECT_EQ(changed, std::vector<std::string>{watched});
  // An editor's save: a temporary file renamed over the original.
  d.Write("ctrl.lua.swp", "-- three");
  ASSERT_EQ(std::rename((d.path() + "/ctrl.lua.swp").c_str(), watched.c_str()), 0);
  ASSERT_TRUE(w.WaitForChange(5000, &changed));
  EXPECT_EQ(changed, std::vector<std::string>{watched});
  // Removed (a change), then recreated (another).
  ASSERT_EQ(std::remove(watched.c_str()), 0);
  ASSERT_TRUE(w.WaitForChange(5000));
  EXPECT_FALSE(w.WaitForChange(50));
  d.Write("ctrl.lua", "-- four");
  ASSERT_TRUE(w.WaitForChange(5000));
}

TEST(ServeFileWatcher, AGoneFolderIsSaid) {
  FileWatcher w;
  w.Watch({"/nonexistent-essaim-folder/ctrl.lua"});
  EXPECT_NE(w.Error().find("cannot watch /nonexistent-essaim-folder"), std::string::npos);
  EXPECT_FALSE(w.WaitForChange(10));
}

TEST(ServeLiveExperiment, AScriptErrorKeepsTheLastGoodWorldAndAFixClearsIt) {
  TempDir d;
  d.Write("helper.lua", "return {speed = 5}\n");
  d.Write("ctrl.lua", std::string("local helper = require('helper')\n") + kCtrl);
  std::string argos = d.Write("experiment.argos", TwoRobots());
  LiveExperiment live(argos, {}, nullptr);
  ASSERT_TRUE(live.Load()) << live.Error();
  EXPECT_EQ(live.run(), 1u);
  std::vector<std::string> inputs = live.InputFiles();
  for (const char* name : {"experiment.argos", "ctrl.lua", "helper.lua"})
    EXPECT_NE(std::find(inputs.begin(), inputs.end(), d.path() + "/" + name), inputs.end()) << name;
  for (int i = 0; i < 5; ++i) EXPECT_EQ(live.Step(), StepStatus::Running);

  Json inspected = ToJson(live.Inspect(0));
  EXPECT_EQ(inspected["id"], "fb0");
  EXPECT_EQ(inspected["globals"]["count"], 5);
  EXPECT_EQ(inspected["globals"]["state"]["target"]["x"], 1.5);
  EXPECT_EQ(inspected["globals"].begin().key(), "count");  // keys sorted, whatever pairs() gives
  EXPECT_FALSE(inspected["globals"].contains("string"));   // the standard library is left out
  EXPECT_FALSE(inspected["globals"].contains("step"));     // and functions
  EXPECT_TRUE(inspected["readings"].contains("positioning"));
  EXPECT_TRUE(live.Inspect(7).IsNull());

  d.Write("ctrl.lua", "function step()\n  robot.wheels.set_velocity(1, 1\nend\n");
  EXPECT_FALSE(live.Load());
  EXPECT_NE(live.Error().find("ctrl.lua:3:"), std::string::npos) << live.Error();
  EXPECT_EQ(live.run(), 1u);
  ASSERT_NE(live.world(), nullptr);
  EXPECT_EQ(live.world()->tick, 5u);  // the last good world stays

  d.Write("ctrl.lua", kCtrl);
  ASSERT_TRUE(live.Load()) << live.Error();
  EXPECT_EQ(live.Error(), "");
  EXPECT_EQ(live.run(), 2u);
  EXPECT_EQ(live.world()->tick, 0u);
  ASSERT_TRUE(live.Reset(7));
  EXPECT_EQ(live.seed(), 7u);
  EXPECT_EQ(live.run(), 3u);
}

TEST(ServeLiveExperiment, StepsAsARunDoes) {
  TempDir d;
  d.Write("ctrl.lua", "function step() robot.wheels.set_velocity(3 + robot.random.uniform(), 4) end\n");
  std::string argos = d.Write("experiment.argos", TwoRobots());
  LiveExperiment live(argos, {}, nullptr);
  ASSERT_TRUE(live.Load()) << live.Error();
  for (int i = 0; i < 30; ++i) live.Step();
  Scene run = Load(d, TwoRobots());
  ASSERT_TRUE(run.ok()) << run.error;
  RunTicks(*run.world, 30);
  EXPECT_EQ(PoseHash(*live.world()), PoseHash(*run.world));
}

}  // namespace
}  // namespace essaim
