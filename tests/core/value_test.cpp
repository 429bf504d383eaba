// The plain value tree (core/value.h) and its JSON form (core/json.cpp): what metrics.json
// and the Python module's lua_global read.
#include "core/value.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/json.h"

namespace essaim {
namespace {

TEST(Value, SetKeepsAKeysPlaceAndTakesTheNewValue) {
  Value map = Value::EmptyMap();
  map.Set("b", Value::OfInteger(1));
  map.Set("a", Value::OfString("x"));
  map.Set("b", Value::OfBool(true));
  ASSERT_EQ(map.map.size(), 2u);
  EXPECT_EQ(map.map[0].first, "b");
  EXPECT_EQ(map.map[0].second.kind, Value::Kind::Bool);
  EXPECT_EQ(ValueJsonText(map), "{\n  \"b\": true,\n  \"a\": \"x\"\n}\n");
}

TEST(Value, JsonKeepsIntegersListsAndWritesNonFiniteAsNull) {
  Value list = Value::EmptyList();
  list.list = {Value::OfInteger(3), Value::OfNumber(0.5), Value::OfNumber(NAN), Value(),
               Value::EmptyMap(),   Value::EmptyList()};
  EXPECT_EQ(DumpJsonLine(ToJson(list)), "[3,0.5,null,null,{},[]]");
  EXPECT_TRUE(Value().IsNull());
  EXPECT_TRUE(ToJson(Value()).is_null());
}

}  // namespace
}  // namespace essaim
