// table, string, package, coroutine, io, os, utf8 and debug are opened at a state's first
// use of them (lua/host/lazy_libraries.cpp): a controller that uses one sees it as before.
#include <gtest/gtest.h>

#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

struct Outcome {
  std::vector<std::string> log;
  std::string error;  // the first controller error, or the load error, or ""
};

// Loads `script` as robot fb0's controller (with `module.lua` and `files` beside it) and
// steps once.
Outcome StepOnce(const std::string& script, bool sandbox = false,
                 const std::vector<std::pair<std::string, std::string>>& files = {}) {
  TempDir d;
  d.Write("c.lua", script);
  d.Write("module.lua", "return {answer = 42}");
  for (const auto& [name, text] : files) d.Write(name, text);
  Outcome run;
  SimOptions so;
  so.lua.sandbox = sandbox;
  so.log_sink = [&run](char, const std::string& line, const LogOrigin&) { run.log.push_back(line); };
  Scene s = Load(d, Experiment(FootBot("fb0", 0, 0, 0, "c"), WheelsController("c", "c.lua")), {}, so);
  if (!s.ok()) {
    run.error = "load failed: " + s.error;
    return run;
  }
  Step(*s.world);
  if (!s.world->controller_errors.empty()) run.error = s.world->controller_errors[0].message;
  return run;
}

TEST(LazyLibraries, EachWorksAtItsFirstUse) {
  Outcome r = StepOnce(R"(
function step()
  io.write("written ", 12, "\n")                      -- routed to the log, as print()
  assert(io.write("x") == io.stdout)
  io.write("\n")
  assert(type(os.clock()) == "number" and os.clock() >= 0)
  assert(math.type(os.time()) == "integer")
  assert(utf8.char(72, 233) == "H\u{e9}" and utf8.len("H\u{e9}") == 2)
  assert(("%d-%s"):format(3, "x") == "3-x" and string.rep("ab", 2) == "abab")
  local t = {}
  table.insert(t, "b")
  table.insert(t, 1, "a")
  assert(table.concat(t, ",") == "a,b")
  local gen = coroutine.wrap(function(a) local b = coroutine.yield(a + 1) return b * 2 end)
  assert(gen(1) == 2 and gen(5) == 10)
  local co = coroutine.create(function() coroutine.yield(7) end)
  local ok, v = coroutine.resume(co)
  assert(ok and v == 7 and coroutine.status(co) == "suspended")
  local ok2, err = pcall(coroutine.wrap(function() error("boom") end))
  assert(not ok2 and err:find("^[^:]*c.lua:19: boom$"), err)  -- one position, as Lua's wrap
  assert(debug.traceback("here"):find("stack traceback:"))
  assert(require("module").answer == 42 and package.loaded.module.answer == 42)
end
)");
  EXPECT_EQ(r.error, "");
  EXPECT_EQ(r.log, (std::vector<std::string>{"written 12", "x"}));
}

TEST(LazyLibraries, TheGlobalIsTheLibrarysTableBeforeAndAfter) {
  Outcome r = StepOnce(R"(
local kept_os, kept_io = os, io          -- references taken before any use
assert(package.loaded.os == kept_os and require("io") == kept_io)
local names = {}
for k in pairs(os) do names[k] = true end  -- pairs() opens it
assert(names.clock and names.time and names.exit)
assert(kept_os.clock == os.clock and rawget(os, "clock") ~= nil)
utf8.mine = 1                              -- a write first: the library, then the field
assert(utf8.mine == 1 and utf8.char(65) == "A")
os.time = function() return 5 end          -- replaced, as a script may
assert(os.time() == 5)
assert(getmetatable(io) == nil or io.write)  -- the loader's metatable goes at first use
assert(io.write and getmetatable(io) == nil)
function step() end
)");
  EXPECT_EQ(r.error, "");
}

TEST(LazyLibraries, StringsHaveTheirMetatableBeforeTheLibraryOpens) {
  Outcome r = StepOnce(R"(
assert("10" + 1 == 11 and "3" * "4" == 12 and -"2" == -2 and "7" // 2 == 3)  -- Lua's coercions
assert(#"abc" == 3 and "a" .. 1 == "a1" and rawget(string, "upper") == nil)   -- not opened yet
assert(getmetatable("").__index == string)
assert(("abc"):upper() == "ABC" and rawget(string, "upper") ~= nil)          -- a method opens it
assert(getmetatable("").__index == string and "5" - 1 == 4)
function string.shout(s) return s:upper() .. "!" end                       -- a script's own method
assert(("hi"):shout() == "HI!")
function step() end
)");
  EXPECT_EQ(r.error, "");
}

TEST(LazyLibraries, RequireOpensPackageAndReadsTheScriptsPath) {
  Outcome r = StepOnce(R"(
local kept = require                                  -- the placeholder's require
assert(rawget(package, "path") == nil)
assert(kept("module").answer == 42 and package.loaded.module.answer == 42)
assert(require ~= kept and type(package.searchers) == "table")  -- Lua's own from now on
local folder = package.path:match("^(.-)%?%.lua")      -- the script's folder comes first
package.path = folder .. "?.mod;" .. package.path     -- read by require's searchers
assert(kept("other").name == "other" and require("other").name == "other")
function step() end
)",
                       false, {{"other.mod", "return {name = 'other'}"}});
  EXPECT_EQ(r.error, "");
}

TEST(LazyLibraries, AScriptsRequireStaysWhenPackageOpens) {
  Outcome r = StepOnce(R"(
local original = require
local calls = 0
local function mine(name) calls = calls + 1 return original(name) end
require = mine
assert(package.config ~= nil and require == mine)     -- package opened by a read
assert(require("module").answer == 42 and calls == 1)
function step() end
)");
  EXPECT_EQ(r.error, "");
}

TEST(LazyLibraries, TheWatchdogsGuardsHoldOnceOpened) {
  Outcome sethook = StepOnce("function step() debug.sethook(print, 'l') end");
  EXPECT_NE(sethook.error.find("debug.sethook is not available"), std::string::npos) << sethook.error;
  Outcome gc = StepOnce("function step() debug.setmetatable({}, {__gc = print}) end");
  EXPECT_NE(gc.error.find("debug.setmetatable: a __gc finalizer is refused"), std::string::npos) << gc.error;
  Outcome exited = StepOnce("function step() os.exit(3) end");
  EXPECT_NE(exited.error.find("os.exit called at"), std::string::npos) << exited.error;
}

TEST(LazyLibraries, UnderTheSandboxOnlyCoroutineAndUtf8AreThere) {
  Outcome r = StepOnce(R"(
function step()
  assert(io == nil and os == nil and debug == nil)
  assert(package.loaded.io == nil and package.loaded.os == nil and package.loaded.debug == nil)
  assert(utf8.char(65) == "A" and package.loaded.utf8 == utf8)
  assert(coroutine.wrap(function() coroutine.yield(3) end)() == 3)
  assert(require("module").answer == 42)
  assert(package.loadlib == nil and package.cpath == "" and package.searchers[3] == nil)
end
)",
                       /*sandbox=*/true);
  EXPECT_EQ(r.error, "");
}

TEST(LazyLibraries, VectorTypesAreMadeWithTheirFirstValue) {
  // No positioning sensor: the script makes the first vector2, vector3 and quaternion.
  Outcome r = StepOnce(R"(
function step()
  local v = vector2(3, 4)
  assert(v:length() == 5 and tostring(v) ~= nil and v == vector2(3, 4))
  local ok, err = pcall(function() return v:dot(5) end)
  assert(not ok and err:find("vector2 expected, got number"), err)
  local w = vector3(1, 0, 0)
  w:rotate(quaternion(math.pi / 2, vector3(0, 0, 1)))
  assert(math.abs(w.y - 1) < 1e-9 and getmetatable(w) ~= getmetatable(v))
end
)");
  EXPECT_EQ(r.error, "");
}

}  // namespace
}  // namespace essaim
