// Lua's io library as controllers and loop functions get it: io.write follows io.output,
// and only what reaches the process's stdout becomes log lines (docs/compatibility.md).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

struct Line {
  char stream;
  std::string text;
  int robot;
};

std::string ReadFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// `script` run by the robots named in `ids` (folder: the TempDir's path in robot.params.dir),
// their log lines kept; `threads` for sense + control.
Scene LoadLogged(const TempDir& d, const std::string& script, const std::vector<std::string>& ids,
                 std::vector<Line>* lines, int threads = 1, const std::string& loop = "") {
  d.Write("c.lua", script);
  std::string arena;
  for (size_t i = 0; i < ids.size(); ++i) arena += FootBot(ids[i], static_cast<double>(i) - 2, 0, 0, "c");
  SimOptions so;
  so.threads = threads;
  so.log_sink = [lines](char s, const std::string& l, const LogOrigin& o) { lines->push_back({s, l, o.robot}); };
  const std::string controller = WheelsController("c", "c.lua", "", "dir=\"" + d.path() + "\"");
  return Load(d, Experiment(arena, controller, 10, 1, loop), {}, so);
}

std::vector<std::string> Texts(const std::vector<Line>& lines) {
  std::vector<std::string> out;
  for (const Line& l : lines) out.push_back(l.text);
  return out;
}

// The issue's reproduction: the file fills, nothing reaches the log.
TEST(LuaIo, IoWriteGoesToTheFileIoOutputNames) {
  TempDir d;
  std::vector<Line> lines;
  Scene s = LoadLogged(d, R"(
function init()
  local f = io.open(robot.params.dir .. "/out_" .. robot.id .. ".txt", "w")
  assert(io.output(f) == f and io.output() == f)
  assert(io.write("hello from ", robot.id, "\n") == f)
  io.close(f)
  io.output(io.stdout)
end
function step() end
)",
                       {"fb0", "fb1"}, &lines);
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 2);
  EXPECT_TRUE(s.world->controller_errors.empty()) << s.world->controller_errors[0].message;
  EXPECT_EQ(ReadFile(d.path() + "/out_fb0.txt"), "hello from fb0\n");
  EXPECT_EQ(ReadFile(d.path() + "/out_fb1.txt"), "hello from fb1\n");
  EXPECT_TRUE(lines.empty()) << lines[0].text;
}

// io.output(name) opens the file for writing; io.close() closes the default output, after
// which io.write raises Lua's error until io.output(io.stdout) brings the log back.
TEST(LuaIo, OutputByNameCloseWithoutArgumentsAndBackToStdout) {
  TempDir d;
  std::vector<Line> lines;
  Scene s = LoadLogged(d, R"(
function init()
  local name = robot.params.dir .. "/rewards.lua"
  local f = io.output(name)
  assert(io.type(f) == "file" and f ~= io.stdout)
  io.write("rewards = {", 1, ", ", 2.5, "}\n")
  assert(io.close() == true and io.type(f) == "closed file")
  local ok, err = pcall(io.write, "lost")
  log(tostring(ok), " ", err)
  assert(io.output(io.stdout) == io.stdout)
  io.write("back on stdout ", 1.0, " ", 3, "\n")
  print(io.close())
end
function step() end
)",
                       {"fb0"}, &lines);
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_EQ(ReadFile(d.path() + "/rewards.lua"), "rewards = {1, 2.5}\n");
  EXPECT_EQ(Texts(lines), (std::vector<std::string>{"false default output file is closed", "back on stdout 1 3",
                                                    "nil\tcannot close standard file"}));
}

// Reading after io.input: io.read and io.lines without a file name read the default input.
TEST(LuaIo, ReadAndLinesFollowIoInput) {
  TempDir d;
  d.Write("in.txt", "first line\n42 7.5\nthird\nfourth\n");
  std::vector<Line> lines;
  Scene s = LoadLogged(d, R"(
function init()
  local f = io.input(robot.params.dir .. "/in.txt")
  assert(io.input() == f)
  log(io.read("l"), "|", io.read("n"), "|", io.read("n"), "|", io.read("L") == "\n")
  for line in io.lines() do log("line ", line) end
  io.close(f)
  for line in io.lines(robot.params.dir .. "/in.txt") do io.write(line, ";") end
  io.write("\n")
end
function step() end
)",
                       {"fb0"}, &lines);
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_EQ(Texts(lines), (std::vector<std::string>{"first line|42|7.5|1", "line third", "line fourth",
                                                    "first line;42 7.5;third;fourth;"}));
}

// What reaches stdout is written as Lua writes it: io.write's numbers with %.14g (1.0 is
// "1"), print's with tostring (1.0), io.stdout:write as io.write, lines joined across
// io.write and print as on a terminal, an empty line kept, a line left open ended with
// the call.
TEST(LuaIo, TextOnStdoutIsWhatLuaWouldPrint) {
  TempDir d;
  std::vector<Line> lines;
  Scene s = LoadLogged(d, R"(
function init()
  assert(io.write(1.0, " ", 2, " ", 0.1, " ", 1e100, "\n") == io.stdout)
  print(1.0, nil, true)
  assert(io.stdout:write("method ", 5, "\n") == io.stdout)
  io.output():write("via output()\n")
  io.write("joined ")
  print("with print")
  io.write("\n")
  io.write("left open")
end
function step() io.write("step ", robot.id) end
)",
                       {"fb0"}, &lines);
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 1);
  EXPECT_EQ(Texts(lines), (std::vector<std::string>{"1 2 0.1 1e+100", "1.0\tnil\ttrue", "method 5", "via output()",
                                                    "joined with print", "", "left open", "step fb0"}));
  for (const Line& l : lines) EXPECT_EQ(l.stream, 'O');
}

// Errors are Lua's own: a table to io.write, a closed file's write.
TEST(LuaIo, ErrorsAreLuas) {
  TempDir d;
  std::vector<Line> lines;
  Scene s = LoadLogged(d, R"(
function init()
  log(select(2, pcall(io.write, {})))
  local f = io.open(robot.params.dir .. "/x.txt", "w")
  f:close()
  log(select(2, pcall(f.write, f, "x")))
  log(select(2, pcall(io.stdout.write, io.stdout, {})))
end
function step() end
)",
                       {"fb0"}, &lines);
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_EQ(Texts(lines), (std::vector<std::string>{"bad argument #1 to 'io.write' (string expected, got table)",
                                                    "attempt to use a closed file",
                                                    "bad argument #2 to '?' (string expected, got table)"}));
}

// Each robot has its own default output, whatever the threads: even robots write every
// step to their own file, odd ones to stdout (the log, in robot order).
void EachRobotHasItsOwnDefaultOutput(int threads) {
  TempDir d;
  std::vector<Line> lines;
  const std::vector<std::string> ids = {"r0", "r1", "r2", "r3", "r4", "r5"};
  Scene s = LoadLogged(d, R"(
local n = 0
function init()
  if tonumber(robot.id:sub(2)) % 2 == 0 then io.output(robot.params.dir .. "/" .. robot.id .. ".txt") end
end
function step()
  n = n + 1
  io.write(robot.id, " ", n, "\n")
  io.flush()
end
)",
                       ids, &lines, threads);
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_EQ(s.world->threads, threads);
  RunTicks(*s.world, 3);
  std::vector<std::string> expected;
  for (int tick = 1; tick <= 3; ++tick)
    for (const char* id : {"r1", "r3", "r5"}) expected.push_back(std::string(id) + " " + std::to_string(tick));
  EXPECT_EQ(Texts(lines), expected);
  for (const char* id : {"r0", "r2", "r4"}) {
    const std::string mine = std::string(id);
    EXPECT_EQ(ReadFile(d.path() + "/" + mine + ".txt"), mine + " 1\n" + mine + " 2\n" + mine + " 3\n") << mine;
  }
}
TEST(LuaIo, EachRobotHasItsOwnDefaultOutputOnOneThread) { EachRobotHasItsOwnDefaultOutput(1); }
TEST(LuaIo, EachRobotHasItsOwnDefaultOutputOnTwoThreads) { EachRobotHasItsOwnDefaultOutput(2); }

// The loop functions get the same io: their files fill, their stdout is their log.
TEST(LuaIo, LoopFunctionsWriteWhereIoOutputSays) {
  TempDir d;
  d.Write("loop.lua", R"(
function init()
  io.output(experiment.params.dir .. "/loop.txt")
  io.write("tick ", experiment.tick, "\n")
  io.close()
  io.output(io.stdout)
  io.write("loop on stdout\n")
  print("loop", "print")
end
)");
  std::vector<Line> lines;
  Scene s = LoadLogged(d, "function step() end", {"fb0"}, &lines, 1,
                       "<loop_functions script=\"loop.lua\" dir=\"" + d.path() + "\"/>");
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_EQ(ReadFile(d.path() + "/loop.txt"), "tick 0\n");
  EXPECT_EQ(Texts(lines), (std::vector<std::string>{"loop on stdout", "loop\tprint"}));
  for (const Line& l : lines) EXPECT_EQ(l.robot, kLogLoopFunctions);
}

// Under the sandbox there is no io: the robot stops with Lua's error and the sandbox's reason.
TEST(LuaIo, SandboxRefusesWritingAndSaysWhy) {
  TempDir d;
  d.Write("c.lua", "function init()\n  io.output(\"x.txt\")\nend\nfunction step() end\n");
  SimOptions so;
  so.lua.sandbox = true;
  Scene s = Load(d, Experiment(FootBot("fb0", 0, 0, 0, "c"), WheelsController("c", "c.lua")), {}, so);
  ASSERT_TRUE(s.ok()) << s.error;
  ASSERT_EQ(s.world->controller_errors.size(), 1u);
  const std::string& message = s.world->controller_errors[0].message;
  const std::string first_line = message.substr(0, message.find('\n'));
  EXPECT_NE(first_line.find("c.lua:2: attempt to index a nil value (global 'io'): --sandbox leaves out io, os, debug, "
                            "dofile and loadfile (docs/sandbox.md)"),
            std::string::npos)
      << message;
}

}  // namespace
}  // namespace essaim
