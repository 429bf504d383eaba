// Range and bearing against hand-computed values: geometry in the receiver's
// frame, the sender's range (strict <), occlusion, one-tick latency, the Lua API, drops,
// ordering, and the grid routing against a brute-force reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/rng.h"
#include "devices/media.h"
#include "lua/robot/bind_byte.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

constexpr char kSilent[] = "function init() end\nfunction step() end\n";

/// A controller with wheels, the RAB actuator and sensor (sensor attributes `rab`).
std::string RabController(const std::string& id, const std::string& script, const std::string& rab = "",
                          bool actuator = true, bool sensor = true) {
  return "<lua_controller id=\"" + id + "\"><actuators><differential_steering implementation=\"default\"/>" +
         (actuator ? "<range_and_bearing implementation=\"default\"/>" : "") +
         "</actuators><sensors><positioning implementation=\"default\"/>" +
         (sensor ? "<range_and_bearing implementation=\"medium\" medium=\"rab\" " + rab + "/>" : "") +
         "</sensors><params script=\"" + script + "\"/></lua_controller>";
}

std::string Bot(const std::string& id, double x, double y, double yaw_deg, const std::string& ctrl,
                const std::string& attrs = "") {
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "<foot-bot id=\"%s\" %s><body position=\"%.17g,%.17g,0\" orientation=\"%g,0,0\"/><controller "
                "config=\"%s\"/></foot-bot>",
                id.c_str(), attrs.c_str(), x, y, yaw_deg, ctrl.c_str());
  return buf;
}

std::string WithMedia(std::string xml, const std::string& media) {
  size_t p = xml.find("<media/>");
  xml.replace(p, 8, "<media>" + media + "</media>");
  return xml;
}

std::string RabExperiment(const std::string& arena, const std::string& controllers, bool occlusions = true) {
  return WithMedia(
      Experiment(arena, controllers, 100000),
      std::string("<range_and_bearing id=\"rab\" check_occlusions=\"") + (occlusions ? "true" : "false") + "\"/>");
}

/// Loads with the log lines collected.
struct LoggedScene {
  std::vector<std::string> lines;
  Scene s;
};
std::unique_ptr<LoggedScene> LoadLogged(const TempDir& d, const std::string& xml) {
  auto ls = std::make_unique<LoggedScene>();
  SimOptions sim;
  LoggedScene* raw = ls.get();
  sim.log_sink = [raw](char, const std::string& line, const LogOrigin&) { raw->lines.push_back(line); };
  ls->s = Load(d, xml, {}, sim);
  return ls;
}

std::vector<int> Senders(const World& w, int r) {
  std::vector<int> out;
  for (const RabPacket& p : w.robots[r].rd.rab) out.push_back(p.sender);
  return out;
}

TEST(RangeAndBearing, RangeAndBearingInTheReceiversFrame) {
  TempDir d;
  d.Write("s.lua", kSilent);
  Scene s = Load(d, RabExperiment(Bot("a", 0, 0, 0, "c") + Bot("b", 1, 0.5, 90, "c"), RabController("c", "s.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 1);
  const auto& ra = s.world->robots[0].rd.rab;
  const auto& rb = s.world->robots[1].rd.rab;
  ASSERT_EQ(ra.size(), 1u);
  ASSERT_EQ(rb.size(), 1u);
  // a (yaw 0) sees b at (1, 0.5): 111.80 cm, bearing atan(0.5).
  EXPECT_EQ(ra[0].sender, 1);
  EXPECT_NEAR(ra[0].range, 111.80339887, 1e-4);
  EXPECT_NEAR(ra[0].horizontal_bearing, 0.46364760900, 1e-6);
  EXPECT_EQ(ra[0].vertical_bearing, 0.0);
  // b faces +Y: a lies at world (-1, -0.5) = local (-0.5, +1): bearing pi - atan(2).
  EXPECT_EQ(rb[0].sender, 0);
  EXPECT_NEAR(rb[0].range, 111.80339887, 1e-4);
  EXPECT_NEAR(rb[0].horizontal_bearing, 2.03444393580, 1e-6);
  EXPECT_EQ(rb[0].vertical_bearing, 0.0);
  EXPECT_EQ(ra[0].size, 10);  // rab_data_size default
}

TEST(RangeAndBearing, TheSendersRangeStrictly) {
  TempDir d;
  d.Write("s.lua", kSilent);
  // 2 m apart: a (range 1) is not heard by b; b (range 3) is heard by a. c has range
  // exactly 2 at exactly 2 m from a: not heard (strict <).
  Scene s =
      Load(d, RabExperiment(Bot("a", 0, 0, 0, "c", "rab_range=\"1\"") + Bot("b", 2, 0, 0, "c", "rab_range=\"3\"") +
                                Bot("c", 0, 2, 0, "c", "rab_range=\"2\""),
                            RabController("c", "s.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 1);
  EXPECT_EQ(Senders(*s.world, 0), std::vector<int>({1}));
  EXPECT_EQ(Senders(*s.world, 1), std::vector<int>());
  EXPECT_EQ(Senders(*s.world, 2), std::vector<int>({1}));  // b at 2.83 m < 3
}

TEST(RangeAndBearing, DifferentMessageSizesDoNotHearEachOther) {
  TempDir d;
  d.Write("s.lua", kSilent);
  Scene s = Load(d, RabExperiment(Bot("a", 0, 0, 0, "c") + Bot("b", 1, 0, 0, "c", "rab_data_size=\"4\""),
                                  RabController("c", "s.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 1);
  EXPECT_TRUE(s.world->robots[0].rd.rab.empty());
  EXPECT_TRUE(s.world->robots[1].rd.rab.empty());
}

TEST(RangeAndBearing, BoxesAndRobotsOcclude) {
  TempDir d;
  d.Write("s.lua", kSilent);
  // Three rows 4 m apart (beyond the 3 m range): a | wall | b;  c | 5 cm box | e;  f g h.
  const std::string wall =
      "<box id=\"wall\" size=\"0.2,0.2,0.5\" movable=\"false\"><body position=\"0,-4,0\" orientation=\"0,0,0\"/></box>";
  const std::string low =
      "<box id=\"low\" size=\"0.2,0.2,0.05\" movable=\"false\"><body position=\"0,0,0\" orientation=\"0,0,0\"/></box>";
  const std::string bots = Bot("a", -1, -4, 0, "c") + Bot("b", 1, -4, 0, "c") + Bot("c", -1, 0, 0, "c") +
                           Bot("e", 1, 0, 0, "c") + Bot("f", -1, 4, 0, "c") + Bot("g", 0, 4, 0, "c") +
                           Bot("h", 1, 4, 0, "c");
  {
    Scene s = Load(d, RabExperiment(wall + low + bots, RabController("c", "s.lua")));
    ASSERT_TRUE(s.ok()) << s.error;
    RunTicks(*s.world, 1);
    EXPECT_EQ(Senders(*s.world, 0), std::vector<int>());  // the wall reaches z = 0.1
    EXPECT_EQ(Senders(*s.world, 1), std::vector<int>());
    EXPECT_EQ(Senders(*s.world, 2), std::vector<int>({3}));  // the 5 cm box does not
    EXPECT_EQ(Senders(*s.world, 4), std::vector<int>({5}));  // h is hidden by g (a foot-bot)
    EXPECT_EQ(Senders(*s.world, 5), std::vector<int>({4, 6}));
    EXPECT_EQ(Senders(*s.world, 6), std::vector<int>({5}));
  }
  {
    Scene s = Load(d, RabExperiment(wall + low + bots, RabController("c", "s.lua"), /*occlusions=*/false));
    ASSERT_TRUE(s.ok()) << s.error;
    RunTicks(*s.world, 1);
    EXPECT_EQ(Senders(*s.world, 0), std::vector<int>({1}));
    EXPECT_EQ(Senders(*s.world, 4), std::vector<int>({5, 6}));
  }
}

TEST(RangeAndBearing, OnlyTheSensorPutsARobotInTheMedium) {
  TempDir d;
  d.Write("s.lua", "function init() robot.range_and_bearing.set_data(1, 9) end\nfunction step() end\n");
  d.Write("q.lua", kSilent);
  // a: actuator only (broadcasts nothing, ARGoS quirk); b: sensor only (heard, zeros);
  // c: both.
  Scene s = Load(d, RabExperiment(Bot("a", 0, 0, 0, "act") + Bot("b", 0.5, 0, 0, "sen") + Bot("c", 1, 0, 0, "both"),
                                  RabController("act", "s.lua", "", true, false) +
                                      RabController("sen", "q.lua", "", false, true) + RabController("both", "s.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 2);
  EXPECT_EQ(Senders(*s.world, 1), std::vector<int>({2}));
  EXPECT_EQ(Senders(*s.world, 2), std::vector<int>({1}));
  ASSERT_EQ(s.world->robots[2].rd.rab.size(), 1u);
  for (int k = 0; k < 10; ++k) EXPECT_EQ(s.world->robots[2].rd.rab[0].data[k], 0);
  ASSERT_EQ(s.world->robots[1].rd.rab.size(), 1u);
  EXPECT_EQ(s.world->robots[1].rd.rab[0].data[0], 9);
}

TEST(RangeAndBearing, OneTickLatencyBothRobotOrders) {
  TempDir d;
  // The sender writes its step number (init: 200); receivers log what they hear.
  d.Write("send.lua",
          "n = 0\nfunction init() robot.range_and_bearing.set_data(1, 200) end\n"
          "function step() n = n + 1; robot.range_and_bearing.set_data(1, n) end\n");
  d.Write("recv.lua",
          "n = 0\nfunction init() end\n"
          "function step() n = n + 1; local m = robot.range_and_bearing[1]\n"
          "  log(robot.id .. ' ' .. n .. ' ' .. (m and tostring(m.data[1]) or 'none')) end\n");
  auto ls = LoadLogged(
      d, RabExperiment(Bot("r0", 0, 0.5, 0, "recv") + Bot("s", 0, 0, 0, "send") + Bot("r2", 0, -0.5, 0, "recv"),
                       RabController("send", "send.lua") + RabController("recv", "recv.lua")));
  ASSERT_TRUE(ls->s.ok()) << ls->s.error;
  RunTicks(*ls->s.world, 4);
  // r0 (before the sender) and r2 (after it) both hear step t's byte at t+1, init's at 1.
  EXPECT_EQ(ls->lines, std::vector<std::string>(
                           {"r0 1 200", "r2 1 200", "r0 2 1", "r2 2 1", "r0 3 2", "r2 3 2", "r0 4 3", "r2 4 3"}));
}

TEST(RangeAndBearing, ClearDataAndLuaTables) {
  TempDir d;
  d.Write("send.lua",
          "n = 0\nfunction init() robot.range_and_bearing.set_data({7, 300, -1, 2.9, 0, 0, 0, 0, 0, 255}) end\n"
          "function step() n = n + 1; if n == 2 then robot.range_and_bearing.clear_data() end end\n");
  d.Write("recv.lua",
          "function init() end\n"
          "function step() local m = robot.range_and_bearing[1]\n"
          "  print(#robot.range_and_bearing, #m.data, math.type(m.data[1]), table.concat(m.data, ','),\n"
          "      math.type(m.range)) end\n");
  auto ls = LoadLogged(d, RabExperiment(Bot("s", 0, 0, 0, "send") + Bot("r", 0.5, 0, 0, "recv"),
                                        RabController("send", "send.lua") + RabController("recv", "recv.lua")));
  ASSERT_TRUE(ls->s.ok()) << ls->s.error;
  RunTicks(*ls->s.world, 3);
  // Bytes are Lua integers; 300 wraps to 44, -1 to 255, 2.9 truncates (C++ cast).
  EXPECT_EQ(ls->lines, std::vector<std::string>({"1\t10\tinteger\t7,44,255,2,0,0,0,0,0,255\tfloat",
                                                 "1\t10\tinteger\t7,44,255,2,0,0,0,0,0,255\tfloat",
                                                 "1\t10\tinteger\t0,0,0,0,0,0,0,0,0,0\tfloat"}));
}

TEST(RangeAndBearing, AKeptMessageStillHoldsItsOwnTick) {
  // ARGoS builds every message and its data table anew each step: a controller that keeps
  // last step's message (or only its data) still reads last step's values, the tables stay
  // plain (no metatable), and the new message is another table. Guards any reuse of them.
  TempDir d;
  d.Write("send.lua",
          "n = 0\nfunction init() robot.range_and_bearing.set_data(1, 100) end\n"
          "function step() n = n + 1; robot.range_and_bearing.set_data(1, n); robot.range_and_bearing.set_data(2, 2 * "
          "n) end\n");
  d.Write("recv.lua", R"(
local kept, kept_data, kept_range, kept_byte
function init() end
function step()
  collectgarbage()  -- a full cycle between the steps: kept tables must survive it untouched
  local m = robot.range_and_bearing[1]
  if kept then
    local keys = 0
    for _ in pairs(kept) do keys = keys + 1 end
    print(tostring(kept ~= m), tostring(kept_data ~= m.data), kept.data[1], kept_data[1],
        tostring(kept.range == kept_range), tostring(getmetatable(kept)), tostring(getmetatable(kept.data)),
        keys, #kept.data, m.data[1], m.data[2])
  end
  kept, kept_data, kept_range = m, m.data, m.range
end
)");
  auto ls = LoadLogged(d, RabExperiment(Bot("s", 0, 0, 0, "send") + Bot("r", 0.5, 0, 0, "recv"),
                                        RabController("send", "send.lua") + RabController("recv", "recv.lua")));
  ASSERT_TRUE(ls->s.ok()) << ls->s.error;
  RunTicks(*ls->s.world, 4);
  // Step t hears the sender's step t-1 (init: 100); the kept one is step t-2's.
  EXPECT_EQ(ls->lines, std::vector<std::string>({"true\ttrue\t100\t100\ttrue\tnil\tnil\t4\t10\t1\t2",
                                                 "true\ttrue\t1\t1\ttrue\tnil\tnil\t4\t10\t2\t4",
                                                 "true\ttrue\t2\t2\ttrue\tnil\tnil\t4\t10\t3\t6"}));
}

TEST(RangeAndBearing, KeptMessagesSurviveTheCollectorsOwnCycles) {
  // No collectgarbage() here: the run's own generational collector (its tuned minor and
  // major multipliers) promotes kept messages through its minor and major cycles while the
  // controller churns garbage. Every kept message and data table must still read what it
  // read when it arrived, 150 ticks later included.
  TempDir d;
  d.Write("send.lua",
          "n = 0\nfunction init() end\n"
          "function step() n = n + 1; robot.range_and_bearing.set_data(1, n % 256); "
          "robot.range_and_bearing.set_data(2, (7 * n) % 256) end\n");
  d.Write("recv.lua", R"(
local kept, first, second, junk = {}, {}, {}, {}
local checked, wrong = 0, 0
function init() end
function step()
  for i = 1, 400 do junk[i % 50 + 1] = {i, tostring(i)} end  -- garbage: many collections
  local m = robot.range_and_bearing[1]
  if m then
    kept[#kept + 1], first[#kept + 1], second[#kept + 1] = m, m.data[1], m.data[2]
  end
  for k = 1, #kept do
    checked = checked + 1
    if kept[k].data[1] ~= first[k] or kept[k].data[2] ~= second[k] or #kept[k].data ~= 10 then wrong = wrong + 1 end
  end
  if #kept == 150 then print(checked, wrong, tostring(kept[1] ~= kept[2]), tostring(kept[1].data ~= kept[2].data)) end
end
)");
  auto ls = LoadLogged(d, RabExperiment(Bot("s", 0, 0, 0, "send") + Bot("r", 0.5, 0, 0, "recv"),
                                        RabController("send", "send.lua") + RabController("recv", "recv.lua")));
  ASSERT_TRUE(ls->s.ok()) << ls->s.error;
  RunTicks(*ls->s.world, 152);
  EXPECT_EQ(ls->lines, std::vector<std::string>({"11325\t0\ttrue\ttrue"}));  // 1 + 2 + ... + 150 checks
}

TEST(RangeAndBearing, SetDataErrors) {
  TempDir d;
  d.Write("bad.lua",
          "local rab = robot.range_and_bearing\n"
          "function init()\n"
          "  rab.set_data({1, 2, 3, 4, 5, 6, 7, 8, 9, 10})\n"
          "  for _, f in ipairs({function() rab.set_data({1, 2, 3}) end,\n"
          "                      function() rab.set_data({1, 2, 3, 4, 5, 6, 7, 8, 9, 'x'}) end,\n"
          "                      function() rab.set_data(0, 1) end,\n"
          "                      function() rab.set_data(11, 1) end,\n"
          "                      function() rab.set_data(1, 2, 3) end,\n"
          "                      function() rab.set_data('a') end}) do\n"
          "    local ok, err = pcall(f); log(ok and 'ok' or err)\n"
          "  end\n"
          "  rab.set_data(10.9, 99)\n"  // index truncated: 10
          "end\nfunction step() end\n");
  d.Write("s.lua", kSilent);
  auto ls = LoadLogged(d, RabExperiment(Bot("a", 0, 0, 0, "bad") + Bot("b", 0.5, 0, 0, "s"),
                                        RabController("bad", "bad.lua") + RabController("s", "s.lua")));
  ASSERT_TRUE(ls->s.ok()) << ls->s.error;
  RunTicks(*ls->s.world, 1);
  ASSERT_EQ(ls->lines.size(), 6u);
  EXPECT_NE(ls->lines[0].find("expects an array of 10 numbers"), std::string::npos) << ls->lines[0];
  EXPECT_NE(ls->lines[1].find("element #10 is not a number"), std::string::npos) << ls->lines[1];
  EXPECT_NE(ls->lines[2].find("idx between 1 and 10"), std::string::npos) << ls->lines[2];
  EXPECT_NE(ls->lines[3].find("idx between 1 and 10"), std::string::npos) << ls->lines[3];
  EXPECT_NE(ls->lines[4].find("one or two arguments"), std::string::npos) << ls->lines[4];
  EXPECT_NE(ls->lines[5].find("table expected"), std::string::npos) << ls->lines[5];
  // The failed calls left the payload as set before them.
  const auto& rb = ls->s.world->robots[1].rd.rab;
  ASSERT_EQ(rb.size(), 1u);
  std::vector<int> got(rb[0].data, rb[0].data + rb[0].size);
  EXPECT_EQ(got, std::vector<int>({1, 2, 3, 4, 5, 6, 7, 8, 9, 99}));
}

TEST(RangeAndBearing, SetDataConvertsEachElementOnceAsACast) {
  // set_data(array) reads each element once (a proxy's __index runs once per element) and
  // converts integers and floats alike: LuaNumberToByte of the element as a double. Beyond
  // +-2^31 (where ARGoS's cast is undefined) an element is refused, naming it, and the
  // payload stays as it was.
  TempDir d;
  d.Write("conv.lua", R"(
local rab = robot.range_and_bearing
reads = 0
function init()
  local proxy = setmetatable({}, {__index = function(_, i) reads = reads + 1; return 3 * i end,
                                  __len = function() return 10 end})
  rab.set_data(proxy)
  print(reads, math.type(2^53 + 1), math.type(9007199254740993))
  rab.set_data({2147483647, -2147483647, 2147483647.5, -2147483647.5, 255.0, -0.5, 1e9, 2^30, -300, 44.7})
  for _, huge in ipairs({9007199254740993, math.mininteger, 1e300, 2^31, -2^31}) do
    local ok, err = pcall(rab.set_data, {1, 2, 3, 4, 5, 6, 7, 8, 9, huge})
    print(ok, err:match('element #10 %S+ is out of range') or err)
  end
end
function step() end
)");
  auto ls = LoadLogged(d, RabExperiment(Bot("a", 0, 0, 0, "conv"), RabController("conv", "conv.lua")));
  ASSERT_TRUE(ls->s.ok()) << ls->s.error;
  EXPECT_EQ(ls->lines,
            std::vector<std::string>(
                {"10\tfloat\tinteger", "false\telement #10 9.0072e+15 is out of range",
                 "false\telement #10 -9.22337e+18 is out of range", "false\telement #10 1e+300 is out of range",
                 "false\telement #10 2.14748e+09 is out of range", "false\telement #10 -2.14748e+09 is out of range"}));
  const double as_read[] = {2147483647.0, -2147483647.0, 2147483647.5, -2147483647.5, 255.0,
                            -0.5,         1e9,           1073741824.0, -300.0,        44.7};
  std::vector<int> want;
  for (double v : as_read) want.push_back(LuaNumberToByte(v));
  EXPECT_EQ(want, std::vector<int>({255, 1, 255, 1, 255, 0, 0, 0, 212, 44}));
  const std::vector<uint8_t>& got = ls->s.world->robots[0].cmd.rab_data;
  EXPECT_EQ(std::vector<int>(got.begin(), got.end()), want);
}

TEST(RangeAndBearing, SetDataOfALargePayloadIsCheckedBeforeWritten) {
  // Payloads longer than the one-pass buffer (256) take the check-then-write path: same
  // errors, same untouched payload on a bad element, same bytes otherwise.
  TempDir d;
  d.Write("big.lua", R"(
local rab = robot.range_and_bearing
function init()
  local t = {}
  for i = 1, 300 do t[i] = i end
  rab.set_data(t)
  for _, bad in ipairs({'x', 0/0, 1/0}) do
    local u = {}
    for i = 1, 300 do u[i] = 7 end
    u[300] = bad
    local ok, err = pcall(rab.set_data, u)
    log(ok and 'ok' or err)
  end
end
function step() end
)");
  auto ls =
      LoadLogged(d, RabExperiment(Bot("a", 0, 0, 0, "big", "rab_data_size=\"300\""), RabController("big", "big.lua")));
  ASSERT_TRUE(ls->s.ok()) << ls->s.error;
  ASSERT_EQ(ls->lines.size(), 3u);
  EXPECT_NE(ls->lines[0].find("element #300 is not a number"), std::string::npos) << ls->lines[0];
  EXPECT_NE(ls->lines[1].find("element #300 is nan"), std::string::npos) << ls->lines[1];
  EXPECT_NE(ls->lines[2].find("element #300 is inf"), std::string::npos) << ls->lines[2];
  const std::vector<uint8_t>& got = ls->s.world->robots[0].cmd.rab_data;
  ASSERT_EQ(got.size(), 300u);
  for (int i = 0; i < 300; ++i) EXPECT_EQ(got[static_cast<size_t>(i)], (i + 1) % 256) << i;
}

TEST(RangeAndBearing, StaleEntriesBecomeNil) {
  TempDir d;
  d.Write("s.lua", kSilent);
  d.Write("go.lua", "function init() robot.wheels.set_velocity(20, 20) end\nfunction step() end\n");
  d.Write("recv.lua",
          "function init() end\n"
          "function step() print(#robot.range_and_bearing, tostring(robot.range_and_bearing[2] == nil)) end\n");
  // r hears a (still) and b, which drives away at 20 cm/s from 0.9 m: out of 1 m in < 1 s.
  auto ls = LoadLogged(
      d,
      RabExperiment(Bot("r", 0, 0, 0, "recv", "rab_range=\"1\"") + Bot("a", 0, 0.5, 0, "s", "rab_range=\"1\"") +
                        Bot("b", 0.9, 0, 0, "go", "rab_range=\"1\""),
                    RabController("recv", "recv.lua") + RabController("s", "s.lua") + RabController("go", "go.lua")));
  ASSERT_TRUE(ls->s.ok()) << ls->s.error;
  RunTicks(*ls->s.world, 15);
  EXPECT_EQ(ls->lines.front(), "2\tfalse");
  EXPECT_EQ(ls->lines.back(), "1\ttrue");
}

TEST(RangeAndBearing, PacketDropStatistics) {
  TempDir d;
  d.Write("s.lua", kSilent);
  // One receiver, four senders around it: 4 packets per tick, 600 ticks.
  Scene s =
      Load(d, RabExperiment(Bot("r", 0, 0, 0, "recv") + Bot("a", 0.5, 0, 0, "s") + Bot("b", -0.5, 0, 0, "s") +
                                Bot("c", 0, 0.5, 0, "s") + Bot("e", 0, -0.5, 0, "s"),
                            RabController("recv", "s.lua", "packet_drop_prob=\"0.3\"") + RabController("s", "s.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  int received = 0, sent = 0;
  for (int t = 0; t < 600; ++t) {
    Step(*s.world);
    received += static_cast<int>(s.world->robots[0].rd.rab.size());
    sent += 4;
    ASSERT_EQ(s.world->robots[1].rd.rab.size(), 3u);  // r, c, e (b is behind r); no drop here
  }
  // 2400 Bernoulli(0.7) trials: sd of the fraction 0.0094; 4 sd.
  EXPECT_NEAR(static_cast<double>(received) / sent, 0.7, 0.0375);
}

TEST(RangeAndBearing, NoiseIsCentredAndDeterministic) {
  TempDir d;
  d.Write("s.lua", kSilent);
  const std::string xml =
      RabExperiment(Bot("r", 0, 0, 0, "recv") + Bot("a", 1, 0, 0, "s"),
                    RabController("recv", "s.lua", "noise_std_dev=\"0.05\"") + RabController("s", "s.lua"));
  double sum_range = 0, sum_bearing = 0;
  std::vector<double> first;
  for (int run = 0; run < 2; ++run) {
    Scene s = Load(d, xml);
    ASSERT_TRUE(s.ok()) << s.error;
    for (int t = 0; t < 400; ++t) {
      Step(*s.world);
      const RabPacket& p = s.world->robots[0].rd.rab.at(0);
      if (run == 0) {
        first.push_back(p.range);
        sum_range += p.range;
        sum_bearing += p.horizontal_bearing;
      } else {
        ASSERT_EQ(first[static_cast<size_t>(t)], p.range);  // same seed, same noise
      }
    }
  }
  EXPECT_NEAR(sum_range / 400, 100.0, 1.5);
  EXPECT_NEAR(sum_bearing / 400, 0.0, 0.01);
  EXPECT_NE(first[0], first[1]);
}

TEST(RangeAndBearing, GridRoutingMatchesAllPairs) {
  // 300 robots spread over the arena with mixed ranges; without occlusions the grid's
  // inboxes must equal the brute-force rule, sorted by sender.
  TempDir d;
  d.Write("s.lua", kSilent);
  Rng rng(7);
  std::string bots;
  std::vector<Vec2> pos;
  std::vector<double> range;
  for (int i = 0; i < 300; ++i) {
    Vec2 p;
    bool ok;
    do {  // no overlaps, so physics leaves them where they are
      p = Vec2(rng.Uniform(-4.5, 4.5), rng.Uniform(-4.5, 4.5));
      ok = true;
      for (const Vec2& q : pos) ok &= (p - q).norm() > 0.2;
    } while (!ok);
    pos.push_back(p);
    range.push_back(i % 3 == 0 ? 0.4 : i % 3 == 1 ? 0.9 : 1.7);
    char attrs[64];
    std::snprintf(attrs, sizeof attrs, "rab_range=\"%g\"", range.back());
    bots += Bot("fb" + std::to_string(i), p.x(), p.y(), 0, "c", attrs);
  }
  Scene s = Load(d, RabExperiment(bots, RabController("c", "s.lua"), /*occlusions=*/false));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 1);
  size_t total = 0;
  for (int r = 0; r < 300; ++r) {
    std::vector<int> expect;
    Pose2 pr = s.world->physics.RobotPose(r);
    for (int k = 0; k < 300; ++k) {
      if (k == r) continue;
      Pose2 pk = s.world->physics.RobotPose(k);
      if (std::hypot(pk.x - pr.x, pk.y - pr.y) < range[static_cast<size_t>(k)]) expect.push_back(k);
    }
    EXPECT_EQ(Senders(*s.world, r), expect) << "robot " << r;
    total += expect.size();
  }
  EXPECT_GT(total, 1000u);  // the test means something
}

TEST(RangeAndBearing, OcclusionMatchesOneRayPerPair) {
  // A dense scene with boxes, cylinders (one too low to matter) and robots without the
  // sensor: the media's occlusion shortcut must agree with a Box2D ray per pair.
  TempDir d;
  d.Write("s.lua", kSilent);
  Rng rng(11);
  std::string arena;
  std::vector<Vec2> taken;
  auto free_spot = [&](double clearance) {
    Vec2 p;
    bool ok;
    do {
      p = Vec2(rng.Uniform(-4, 4), rng.Uniform(-4, 4));
      ok = true;
      for (const Vec2& q : taken) ok &= (p - q).norm() > clearance;
    } while (!ok);
    taken.push_back(p);
    return p;
  };
  for (int k = 0; k < 25; ++k) {
    Vec2 p = free_spot(0.5);
    char buf[256];
    if (k % 3 == 0)
      std::snprintf(buf, sizeof buf,
                    "<cylinder id=\"c%d\" radius=\"0.12\" height=\"%s\" movable=\"false\"><body position=\"%g,%g,0\" "
                    "orientation=\"0,0,0\"/></cylinder>",
                    k, k % 2 ? "0.05" : "0.3", p.x(), p.y());
    else
      std::snprintf(buf, sizeof buf,
                    "<box id=\"b%d\" size=\"0.3,0.1,0.2\" movable=\"%s\" mass=\"1\"><body position=\"%g,%g,0\" "
                    "orientation=\"%d,0,0\"/></box>",
                    k, k % 2 ? "true" : "false", p.x(), p.y(), k * 37);
    arena += buf;
  }
  for (int i = 0; i < 250; ++i) {
    Vec2 p = free_spot(0.4);
    arena += Bot("fb" + std::to_string(i), p.x(), p.y(), 0, i % 7 == 3 ? "blind" : "c", "rab_range=\"2\"");
  }
  Scene s =
      Load(d, RabExperiment(arena, RabController("c", "s.lua") + RabController("blind", "s.lua", "", true, false)));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 1);
  size_t heard = 0, hidden = 0;
  for (int r = 0; r < 250; ++r) {
    if (r % 7 == 3) continue;
    std::vector<int> expect;
    Pose2 pr = s.world->physics.RobotPose(r);
    for (int k = 0; k < 250; ++k) {
      if (k == r || k % 7 == 3) continue;
      Pose2 pk = s.world->physics.RobotPose(k);
      if (std::hypot(pk.x - pr.x, pk.y - pr.y) >= 2) continue;
      RayHit hit = s.world->physics.CastRay(Vec2(pr.x, pr.y), Vec2(pk.x, pk.y), 0.1, r);
      // The partner's body or gripper disc is the partner (ARGoS: the same entity).
      const bool partner = (hit.kind == BodyKind::Robot || hit.kind == BodyKind::Gripper) && hit.index == k;
      if (hit.Hit() && !partner) {
        ++hidden;
        continue;
      }
      expect.push_back(k);
    }
    EXPECT_EQ(Senders(*s.world, r), expect) << "robot " << r;
    heard += expect.size();
  }
  EXPECT_GT(heard, 500u);
  EXPECT_GT(hidden, 500u);
}

TEST(RangeAndBearing, ThreadCountDoesNotChangeTheRun) {
  // Robots steer by what they hear and see, with drop and noise on: 1 and 3 threads must
  // give the same poses (receivers draw from their own streams; media are single-threaded).
  TempDir d;
  d.Write("steer.lua", R"(
function init() robot.colored_blob_omnidirectional_camera.enable(); robot.leds.set_all_colors("red") end
function step()
  local turn = 0
  for i = 1, #robot.range_and_bearing do
    local m = robot.range_and_bearing[i]
    turn = turn + m.horizontal_bearing / m.range + m.data[1] / 1000
  end
  for i = 1, #robot.colored_blob_omnidirectional_camera do
    turn = turn - robot.colored_blob_omnidirectional_camera[i].angle / 10
  end
  robot.range_and_bearing.set_data(1, math.floor(robot.random.uniform(0, 255)))
  robot.wheels.set_velocity(10 - 5 * turn, 10 + 5 * turn)
end
)");
  std::string ctrl =
      "<lua_controller id=\"c\"><actuators><differential_steering implementation=\"default\"/>"
      "<leds implementation=\"default\" medium=\"leds\"/><range_and_bearing implementation=\"default\"/></actuators>"
      "<sensors><range_and_bearing implementation=\"medium\" medium=\"rab\" noise_std_dev=\"0.02\" "
      "packet_drop_prob=\"0.2\"/>"
      "<colored_blob_omnidirectional_camera implementation=\"rot_z_only\" medium=\"leds\" "
      "noise_std_dev=\"0.05\"/></sensors>"
      "<params script=\"steer.lua\"/></lua_controller>";
  std::string bots;
  for (int i = 0; i < 60; ++i)
    bots += Bot("fb" + std::to_string(i), -3 + (i % 8) * 0.6, -3 + (i / 8) * 0.6, i * 17, "c", "rab_range=\"1.5\"");
  std::string xml = WithMedia(Experiment(bots, ctrl, 100000), "<range_and_bearing id=\"rab\"/><led id=\"leds\"/>");
  uint64_t hash[2];
  for (int k = 0; k < 2; ++k) {
    SimOptions sim;
    sim.threads = k == 0 ? 1 : 3;
    Scene s = Load(d, xml, {}, sim);
    ASSERT_TRUE(s.ok()) << s.error;
    RunTicks(*s.world, 60);
    EXPECT_TRUE(s.world->controller_errors.empty()) << s.world->controller_errors.front().message;
    hash[k] = PoseHash(*s.world);
  }
  EXPECT_EQ(hash[0], hash[1]);
}

}  // namespace
}  // namespace essaim

namespace essaim {
namespace {
using namespace essaim::testing;

/// Inboxes by brute force on the media's own positions: every pair of members in range,
/// hidden when any other robot's body or gripper disc is entered before the partner's first
/// shape (CircleEntry over all of them, from the lower index as the media does): no grid,
/// cut-off or probe.
std::vector<std::vector<int>> BruteForceInboxes(const Model& model, const Media& m) {
  const int n = static_cast<int>(m.rab_pos.size());
  std::vector<std::vector<int>> inbox(n);
  for (int lo = 0; lo < n; ++lo)
    for (int hi = lo + 1; hi < n; ++hi) {
      if (!m.rab_member[lo] || !m.rab_member[hi]) continue;
      const double d = (m.rab_pos[hi] - m.rab_pos[lo]).norm();
      const bool lo_hears = d < model.robots[hi].rab_range, hi_hears = d < model.robots[lo].rab_range;
      if (!lo_hears && !hi_hears) continue;
      const Vec2 a = m.rab_pos[lo].head<2>(), b = m.rab_pos[hi].head<2>();
      const double len = (b - a).norm();
      const double t_body = len > 0 ? std::max(0.0, len - footbot::kRadius) / len : 0.0;
      const double t_b = std::min(t_body, CircleEntry(a, b, m.gripper_xy[hi], kGripperRadius));
      bool hidden = false;
      for (int c = 0; c < n && !hidden; ++c)
        hidden = c != lo && c != hi &&
                 (CircleEntry(a, b, m.body_xy[c], footbot::kRadius) < t_b ||
                  CircleEntry(a, b, m.gripper_xy[c], kGripperRadius) < t_b);
      if (hidden) continue;
      if (lo_hears) inbox[lo].push_back(hi);
      if (hi_hears) inbox[hi].push_back(lo);
    }
  for (auto& v : inbox) std::sort(v.begin(), v.end());
  return inbox;
}

/// Runs one tick of `bots` (no obstacles, occlusions on) and compares every inbox with the
/// brute force; returns the packets heard and the pairs in range found hidden.
std::pair<size_t, size_t> CheckCrowd(const std::string& bots) {
  TempDir d;
  d.Write("s.lua", kSilent);
  Scene s = Load(d, RabExperiment(bots, RabController("c", "s.lua")));
  EXPECT_TRUE(s.ok()) << s.error;
  if (!s.ok()) return {0, 0};
  RunTicks(*s.world, 1);
  const Media& m = s.world->media;
  std::vector<std::vector<int>> expect = BruteForceInboxes(s.world->model, m);
  size_t heard = 0, in_range = 0;
  const int n = static_cast<int>(expect.size());
  for (int r = 0; r < n; ++r) {
    EXPECT_EQ(Senders(*s.world, r), expect[r]) << "robot " << r;
    heard += expect[r].size();
    for (int k = 0; k < n; ++k)
      in_range += k != r && (m.rab_pos[k] - m.rab_pos[r]).norm() < s.world->model.robots[k].rab_range;
  }
  return {heard, in_range - heard};
}

TEST(RangeAndBearing, CrowdOcclusionMatchesBruteForce) {
  // Crowds dense enough for the media's blocker probes (rab::kCrowd bodies within
  // kBlockerReach), bodies all but touching, and mixed ranges: every inbox equals the
  // brute-force rule.
  for (uint64_t seed : {3, 4}) {
    Rng rng(seed);
    std::vector<Vec2> pos;
    std::string bots;
    for (int i = 0; i < 230; ++i) {
      Vec2 p;
      bool ok;
      do {  // clearance 2 mm above touching: physics leaves them in place
        p = Vec2(rng.Uniform(-1.8, 1.8), rng.Uniform(-1.8, 1.8));
        ok = true;
        for (const Vec2& q : pos) ok &= (p - q).norm() > 2 * footbot::kRadius + 0.002;
      } while (!ok);
      pos.push_back(p);
      bots += Bot("fb" + std::to_string(i), p.x(), p.y(), 0, "c", i % 5 == 0 ? "rab_range=\"1.2\"" : "");
    }
    auto [heard, hidden] = CheckCrowd(bots);
    EXPECT_GT(heard, 1500u);
    EXPECT_GT(hidden, 10000u);  // the crowd hides most pairs
  }
}

TEST(RangeAndBearing, GrazingAndTangentOccludersMatchBruteForce) {
  // Around each of a few devices: a ring of bodies all but touching it, and partners
  // placed along the ring bodies' tangent lines (a hair inside or outside) and through
  // the gaps between them, with a crowd behind: rays that graze, touch or just miss.
  std::string bots;
  int id = 0;
  Rng rng(5);
  const double r = footbot::kRadius;
  for (int cell = 0; cell < 4; ++cell) {
    const Vec2 o(-3 + 4 * (cell % 2), -3 + 4 * (cell / 2));
    std::vector<Vec2> pos{o};
    auto add = [&](const Vec2& p) {
      for (const Vec2& q : pos)
        if ((p - q).norm() <= 2 * r + 1e-3) return;
      pos.push_back(p);
    };
    const int ring = 6 + cell;
    for (int k = 0; k < ring; ++k) {
      const double ang = 2 * M_PI * k / ring + 0.1 * cell;
      const double dist = 2 * r + 0.0015 + 0.01 * (k % 3);
      add(o + dist * Vec2(std::cos(ang), std::sin(ang)));
    }
    for (int k = 0; k < ring; ++k) {
      // Tangent directions of ring body k seen from o, shifted by ±1e-6 rad or not at all.
      const Vec2 c = pos[1 + std::min(k, static_cast<int>(pos.size()) - 2)] - o;
      const double half = std::asin(r / c.norm()), mid = std::atan2(c.y(), c.x());
      for (double side : {-1.0, 1.0})
        for (double eps : {-1e-6, 0.0, 1e-6})
          add(o +
              rng.Uniform(0.5, 1.4) * Vec2(std::cos(mid + side * (half + eps)), std::sin(mid + side * (half + eps))));
    }
    for (int k = 0; k < 60; ++k) add(o + Vec2(rng.Uniform(-1.6, 1.6), rng.Uniform(-1.6, 1.6)));
    for (const Vec2& p : pos) bots += Bot("fb" + std::to_string(id++), p.x(), p.y(), 0, "c");
  }
  auto [heard, hidden] = CheckCrowd(bots);
  EXPECT_GT(heard, 300u);
  EXPECT_GT(hidden, 1000u);
}

}  // namespace
}  // namespace essaim
