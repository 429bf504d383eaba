// A controller's Lua global as a value tree, checked through its JSON form (LuaGlobalToValue,
// behind the Python module's lua_global).
#include "lua/loop/lua_copy.h"

#include <gtest/gtest.h>

#include "core/json.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

struct Globals {
  TempDir dir;
  Scene scene;
  explicit Globals(const std::string& script) {
    dir.Write("c.lua", script + "\nfunction init() end\nfunction step() end\n");
    scene = Load(dir, Experiment(FootBot("fb0", 0, 0, 0, "c"), WheelsController("c", "c.lua")));
  }
  bool Get(const std::string& name, Json* out, std::string* error) {
    Value value;
    if (!LuaGlobalToValue(LuaStateOf(scene.world->controllers[0].get()), name, &value, error)) return false;
    *out = ToJson(value);
    return true;
  }
};

TEST(LuaGlobalToValue, PlainValuesArraysAndObjects) {
  Globals g(R"(
n, x, s, yes, f = 7, 0.25, "text", true, function() end
list = {1, "two", {3}}
map = {a = 1, [2] = "b", [1.5] = false, nested = {deep = {1, 2}}}
holey = {[1] = "a", [3] = "c"}
empty = {}
shared = {1}
twice = {left = shared, right = shared}
)");
  ASSERT_TRUE(g.scene.ok()) << g.scene.error;
  Json v;
  std::string error;
  ASSERT_TRUE(g.Get("n", &v, &error)) << error;
  EXPECT_EQ(v, Json(7));
  ASSERT_TRUE(g.Get("x", &v, &error));
  EXPECT_EQ(v, Json(0.25));
  ASSERT_TRUE(g.Get("s", &v, &error));
  EXPECT_EQ(v, Json("text"));
  ASSERT_TRUE(g.Get("yes", &v, &error));
  EXPECT_EQ(v, Json(true));
  ASSERT_TRUE(g.Get("f", &v, &error));  // a function has no value to copy
  EXPECT_TRUE(v.is_null());
  ASSERT_TRUE(g.Get("unset", &v, &error));
  EXPECT_TRUE(v.is_null());
  ASSERT_TRUE(g.Get("list", &v, &error));
  EXPECT_EQ(v, Json::parse(R"([1, "two", [3]])"));
  ASSERT_TRUE(g.Get("map", &v, &error));
  EXPECT_EQ(v["a"], Json(1));
  EXPECT_EQ(v["2"], Json("b"));
  EXPECT_EQ(v["1.5"], Json(false));
  EXPECT_EQ(v["nested"]["deep"], Json::parse("[1, 2]"));
  ASSERT_TRUE(g.Get("holey", &v, &error));  // keys 1 and 3: not an array
  EXPECT_EQ(v, Json::parse(R"({"1": "a", "3": "c"})"));
  ASSERT_TRUE(g.Get("empty", &v, &error));
  EXPECT_EQ(v, Json::object());
  ASSERT_TRUE(g.Get("twice", &v, &error));  // a shared table is written where it appears
  EXPECT_EQ(v["left"], Json::parse("[1]"));
  EXPECT_EQ(v["right"], Json::parse("[1]"));
}

TEST(LuaGlobalToValue, CyclesAndTableKeysAreRefused) {
  Globals g(R"(
loop = {}
loop.self = loop
keyed = {[{}] = 1}
)");
  ASSERT_TRUE(g.scene.ok()) << g.scene.error;
  Json v;
  std::string error;
  EXPECT_FALSE(g.Get("loop", &v, &error));
  EXPECT_NE(error.find("contains itself"), std::string::npos) << error;
  EXPECT_FALSE(g.Get("keyed", &v, &error));
  EXPECT_NE(error.find("used as a key"), std::string::npos) << error;
  Value none;
  EXPECT_FALSE(LuaGlobalToValue(nullptr, "x", &none, &error));
  EXPECT_NE(error.find("not running"), std::string::npos) << error;
}

}  // namespace
}  // namespace essaim
