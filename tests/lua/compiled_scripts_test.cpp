// Controller scripts compiled once per run (lua/host/compiled_scripts.h): one parse per
// file, later states load its bytecode, and errors still name the file and line.
#include "lua/host/compiled_scripts.h"

#include <gtest/gtest.h>

#include <lua.hpp>

#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

struct StockState {
  lua_State* L = luaL_newstate();
  ~StockState() { lua_close(L); }
};

/// `code` compiled and dumped, as luac would write it.
std::string Bytecode(const char* code) {
  StockState s;
  std::string bytes;
  if (luaL_loadstring(s.L, code) != LUA_OK) return bytes;
  lua_dump(
      s.L,
      [](lua_State*, const void* p, size_t n, void* out) {
        static_cast<std::string*>(out)->append(static_cast<const char*>(p), n);
        return 0;
      },
      &bytes, 0);
  return bytes;
}

TEST(CompiledScripts, LaterStatesRunTheFirstParseAndTheFileIsReadOnce) {
  TempDir d;
  const std::string path = d.Write("c.lua", "return 1");
  CompiledScripts scripts;
  StockState a, b;
  ASSERT_EQ(scripts.Load(a.L, path, false), LUA_OK);
  ASSERT_EQ(lua_pcall(a.L, 0, 1, 0), LUA_OK);
  EXPECT_EQ(lua_tointeger(a.L, -1), 1);
  // The file changes on disk: the second state still runs the chunk parsed first.
  d.Write("c.lua", "return 2");
  ASSERT_EQ(scripts.Load(b.L, path, false), LUA_OK);
  ASSERT_EQ(lua_pcall(b.L, 0, 1, 0), LUA_OK);
  EXPECT_EQ(lua_tointeger(b.L, -1), 1);
  EXPECT_EQ(scripts.Parsed(), 1u);
}

TEST(CompiledScripts, ASyntaxErrorNamesFileAndLineAndEveryLaterStateGetsTheSame) {
  TempDir d;
  const std::string path = d.Write("bad.lua", "local x = 1\nfunction step(\n");
  CompiledScripts scripts;
  StockState a;
  ASSERT_EQ(scripts.Load(a.L, path, false), LUA_ERRSYNTAX);
  const std::string message = lua_tostring(a.L, -1);
  EXPECT_NE(message.find("bad.lua:3:"), std::string::npos) << message;
  EXPECT_EQ(scripts.Parsed(), 0u);
  // The run's other states get the first parse's error, the file not read again.
  d.Write("bad.lua", "return 1");
  StockState b;
  ASSERT_EQ(scripts.Load(b.L, path, false), LUA_ERRSYNTAX);
  EXPECT_EQ(lua_tostring(b.L, -1), message);
}

TEST(CompiledScripts, HostTextIsCompiledOnceAndRunsTheSameInEveryState) {
  CompiledScripts scripts;
  const char text[] = "local a, b = ...\nreturn a * 10 + b";
  StockState a, b;
  ASSERT_EQ(scripts.LoadText(a.L, "=host", text, sizeof text - 1), LUA_OK);
  ASSERT_EQ(scripts.LoadText(b.L, "=host", "not Lua at all", 14), LUA_OK);  // the first text's bytecode
  for (lua_State* L : {a.L, b.L}) {
    lua_pushinteger(L, 4);
    lua_pushinteger(L, 2);
    ASSERT_EQ(lua_pcall(L, 2, 1, 0), LUA_OK) << lua_tostring(L, -1);
    EXPECT_EQ(lua_tointeger(L, -1), 42);
  }
  EXPECT_EQ(scripts.Parsed(), 0u);  // host text is not a script file
}

TEST(CompiledScripts, TextOnlyRefusesABinaryFile) {
  TempDir d;
  StockState a;
  // A real chunk, dumped: accepted from a file outside the sandbox, as by luaL_loadfile.
  const std::string path = d.Write("compiled.lua", Bytecode("return 3"));
  CompiledScripts scripts;
  EXPECT_EQ(scripts.Load(a.L, path, false), LUA_OK);
  StockState b;
  ASSERT_EQ(scripts.Load(b.L, path, true), LUA_ERRSYNTAX);
  const std::string message = lua_tostring(b.L, -1);
  EXPECT_NE(message.find("attempt to load a binary chunk (mode is 't')"), std::string::npos) << message;
}

TEST(CompiledScripts, EveryRobotsErrorsNameTheScriptLineAsBefore) {
  TempDir d;
  d.Write("c.lua", R"(local n = 0
function init() end
function step()
  n = n + 1
  if robot.id ~= "fb0" then error("boom " .. robot.id) end
end
)");
  const std::string ctrl = WheelsController("c", "c.lua");
  Scene s = Load(
      d, Experiment(FootBot("fb0", 0, 0, 0, "c") + FootBot("fb1", 1, 0, 0, "c") + FootBot("fb2", 2, 0, 0, "c"), ctrl));
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_EQ(s.world->scripts.Parsed(), 1u);
  Step(*s.world);
  ASSERT_EQ(s.world->controller_errors.size(), 2u);
  for (const ControllerError& e : s.world->controller_errors) {
    EXPECT_NE(e.message.find("c.lua:5: boom " + e.robot), std::string::npos) << e.message;
    EXPECT_NE(e.message.find("c.lua:5: in function 'step'"), std::string::npos) << e.message;
  }
}

TEST(CompiledScripts, ASandboxedControllerFileMustBeText) {
  TempDir d;
  d.Write("c.lua", Bytecode("function step() end"));
  SimOptions so;
  so.lua.sandbox = true;
  Scene s = Load(d, Experiment(FootBot("fb0", 0, 0, 0, "c"), WheelsController("c", "c.lua")), {}, so);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.error.find("robot fb0: "), std::string::npos) << s.error;
  EXPECT_NE(s.error.find("attempt to load a binary chunk"), std::string::npos) << s.error;
}

}  // namespace
}  // namespace essaim
