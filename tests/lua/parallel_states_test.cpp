// Controllers' states made and their init() run on the World's threads: what is reported
// is what a serial loop over the robots reports, whatever the thread count.
#include <gtest/gtest.h>

#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

// Robots fb0..fb7 at x = -3.5..3.5, each with controller "c<k>" from `controller_of`.
std::string EightRobots(const std::string& controller_of) {
  std::string arena;
  for (int i = 0; i < 8; ++i)
    arena += FootBot("fb" + std::to_string(i), i - 3.5, 0, 0, std::string("c") + controller_of[static_cast<size_t>(i)]);
  return arena;
}

Scene LoadOnThreads(const TempDir& d, const std::string& xml, int threads, bool strict = false,
                    std::vector<std::string>* log = nullptr) {
  SimOptions so;
  so.threads = threads;
  so.strict = strict;
  if (log) so.log_sink = [log](char, const std::string& line, const LogOrigin&) { log->push_back(line); };
  return Load(d, xml, {}, so);
}

TEST(ParallelStates, TheLowestRobotsLoadErrorIsReported) {
  TempDir d;
  d.Write("ok.lua", "function step() end\n");
  d.Write("syntax.lua", "function step(\n");
  d.Write("raises.lua", "error('top level of ' .. robot.id)\nfunction step() end\n");
  const std::string controllers =
      WheelsController("c0", "ok.lua") + WheelsController("c1", "syntax.lua") + WheelsController("c2", "raises.lua");
  for (int threads : {1, 2, 4}) {
    // fb2 raises at its top level, fb6 has a syntax error: fb2's error, as serially.
    Scene a = LoadOnThreads(d, Experiment(EightRobots("00200010"), controllers), threads);
    ASSERT_FALSE(a.ok());
    EXPECT_NE(a.error.find("robot fb2: "), std::string::npos) << a.error;
    EXPECT_NE(a.error.find("raises.lua:1: top level of fb2"), std::string::npos) << a.error;
    // The other way round: fb1's syntax error comes first.
    Scene b = LoadOnThreads(d, Experiment(EightRobots("01000020"), controllers), threads);
    ASSERT_FALSE(b.ok());
    EXPECT_EQ(b.error.rfind("robot fb1: ", 0), 0u) << b.error;
    EXPECT_NE(b.error.find("syntax.lua:2:"), std::string::npos) << b.error;
  }
}

TEST(ParallelStates, InitErrorsComeInRobotOrderAndStrictStopsAtTheFirst) {
  TempDir d;
  d.Write("c.lua", R"(
function init()
  log("init " .. robot.id)
  if robot.id == "fb3" or robot.id == "fb6" then error("init failed on " .. robot.id) end
end
function step() end
)");
  const std::string xml = Experiment(EightRobots("00000000"), WheelsController("c0", "c.lua"));
  for (int threads : {1, 2}) {
    Scene s = LoadOnThreads(d, xml, threads);
    ASSERT_TRUE(s.ok()) << s.error;
    ASSERT_EQ(s.world->controller_errors.size(), 2u);
    EXPECT_EQ(s.world->controller_errors[0].robot, "fb3");
    EXPECT_EQ(s.world->controller_errors[1].robot, "fb6");
    EXPECT_FALSE(s.world->robots[3].controller_ok);
    EXPECT_TRUE(s.world->robots[4].controller_ok);
    EXPECT_TRUE(s.world->failure.empty()) << s.world->failure;

    // Strict: fb3's error ends the run; fb6's is never reported, and the robots after fb3
    // log nothing of their init(), as when init() ran one robot after another.
    std::vector<std::string> log;
    Scene t = LoadOnThreads(d, xml, threads, /*strict=*/true, &log);
    ASSERT_TRUE(t.ok()) << t.error;
    ASSERT_EQ(t.world->controller_errors.size(), 1u);
    EXPECT_EQ(t.world->controller_errors[0].robot, "fb3");
    EXPECT_NE(t.world->failure.find("init failed on fb3"), std::string::npos) << t.world->failure;
    const std::vector<std::string> inits(log.begin(), log.begin() + 4);
    EXPECT_EQ(inits, (std::vector<std::string>{"init fb0", "init fb1", "init fb2", "init fb3"}));
    for (const std::string& line : log) EXPECT_EQ(line.find("init fb4"), std::string::npos) << line;
    for (const std::string& line : log) EXPECT_EQ(line.find("init fb7"), std::string::npos) << line;
  }
}

TEST(ParallelStates, TheWatchdogStopsARunawayOnAnyThread) {
  // Not sandboxed: the count hook is armed only by the watchdog's thread, through the slot
  // of whichever of the pool's threads runs the call.
  TempDir d;
  d.Write("ok.lua", "function init() end\nfunction step() end\n");
  d.Write("loops.lua", "while true do end\n");
  d.Write("loops_in_init.lua", "function init() while true do end end\nfunction step() end\n");
  const std::string controllers = WheelsController("c0", "ok.lua") + WheelsController("c1", "loops.lua") +
                                  WheelsController("c2", "loops_in_init.lua");
  SimOptions so;
  so.threads = 2;
  so.lua.instruction_limit = so.lua.setup_instruction_limit = 1000000;
  Scene chunk = Load(d, Experiment(EightRobots("00000010"), controllers), {}, so);
  ASSERT_FALSE(chunk.ok());
  EXPECT_EQ(chunk.error.rfind("robot fb6: ", 0), 0u) << chunk.error;
  EXPECT_NE(chunk.error.find("instruction budget exceeded"), std::string::npos) << chunk.error;
  Scene init = Load(d, Experiment(EightRobots("00000002"), controllers), {}, so);
  ASSERT_TRUE(init.ok()) << init.error;
  ASSERT_EQ(init.world->controller_errors.size(), 1u);
  EXPECT_EQ(init.world->controller_errors[0].robot, "fb7");
  EXPECT_NE(init.world->controller_errors[0].message.find("instruction budget exceeded"), std::string::npos)
      << init.world->controller_errors[0].message;
}

}  // namespace
}  // namespace essaim
