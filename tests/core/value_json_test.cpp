// A value tree as JSON text and back (core/value_json.h): what the live server's answers,
// its control commands, --set-file and summary.json go through without the JSON library.
#include "core/value_json.h"

#include <gtest/gtest.h>

#include "core/json.h"

namespace essaim {
namespace {

Value Parsed(const std::string& text) {
  Value v;
  std::string error;
  EXPECT_TRUE(ParseJsonValue(text, &v, &error)) << error;
  return v;
}

TEST(ValueJson, IntegersStayIntegersAndNumbersStayNumbers) {
  Value v = Parsed(R"({"b": 2.5, "a": 9007199254740993, "n": -3, "one": 1.0, "big": 18446744073709551615})");
  ASSERT_EQ(v.kind, Value::Kind::Map);
  ASSERT_EQ(v.map.size(), 5u);
  EXPECT_EQ(v.map[0].first, "b");  // the text's order, not sorted
  EXPECT_EQ(v.map[0].second.kind, Value::Kind::Number);
  EXPECT_EQ(v.map[0].second.number, 2.5);
  EXPECT_EQ(v.Find("a")->kind, Value::Kind::Integer);
  EXPECT_EQ(v.Find("a")->integer, 9007199254740993);  // not rounded through a double
  EXPECT_EQ(v.Find("n")->integer, -3);
  EXPECT_EQ(v.Find("one")->kind, Value::Kind::Number);
  EXPECT_EQ(v.Find("big")->kind, Value::Kind::Unsigned);
  EXPECT_EQ(v.Find("big")->big_unsigned, 18446744073709551615ULL);
  EXPECT_EQ(ValueJsonLine(v), R"({"b":2.5,"a":9007199254740993,"n":-3,"one":1.0,"big":18446744073709551615})");
}

TEST(ValueJson, NestingRoundTripsOnOneLineAndPretty) {
  const std::string line = R"({"x":[1,{"y":null,"z":[true,"s\n"]}],"e":{},"l":[]})";
  Value v = Parsed(line);
  ASSERT_EQ(v.Find("x")->kind, Value::Kind::List);
  const Value& inner = v.Find("x")->list[1];
  EXPECT_TRUE(inner.Find("y")->IsNull());
  EXPECT_EQ(inner.Find("z")->list[0].kind, Value::Kind::Bool);
  EXPECT_EQ(inner.Find("z")->list[1].text, "s\n");
  EXPECT_EQ(v.Find("e")->kind, Value::Kind::Map);
  EXPECT_EQ(ValueJsonLine(v), line);
  EXPECT_EQ(ValueJsonText(Parsed(R"({"a": [1, 2]})")), "{\n  \"a\": [\n    1,\n    2\n  ]\n}\n");
  EXPECT_EQ(ValueJsonLine(Parsed("7")), "7");
}

TEST(ValueJson, ARepeatedKeyKeepsItsFirstPlaceAndItsLastValue) {
  Value v = Parsed(R"({"a": 1, "b": 2, "a": 3})");
  ASSERT_EQ(v.map.size(), 2u);
  EXPECT_EQ(v.map[0].first, "a");
  EXPECT_EQ(v.map[0].second.integer, 3);
}

TEST(ValueJson, RejectsWhatParseJsonRejectsWithTheSameError) {
  for (const std::string text : {"{\"a\": 1,\n }", "", "[1, 2", "{} x", "{'a': 1}", "nan", "01"}) {
    Value v = Value::OfInteger(5);
    std::string value_error, json_error;
    Json doc;
    EXPECT_FALSE(ParseJsonValue(text, &v, &value_error)) << text;
    EXPECT_FALSE(ParseJson(text, &doc, &json_error)) << text;
    EXPECT_EQ(value_error, json_error);
    EXPECT_EQ(value_error.rfind("invalid JSON at line ", 0), 0u) << value_error;
    EXPECT_EQ(v.integer, 5);  // left as it was
  }
  std::string error;
  Value v;
  EXPECT_FALSE(ParseJsonValue("{\"a\": 1,\n }", &v, &error));
  EXPECT_NE(error.find("invalid JSON at line 2, column 2"), std::string::npos) << error;
}

TEST(ValueJson, FindMapOfAndOfUnsigned) {
  Value m = Value::MapOf({{"k", Value::OfStrings({"a", "b"})}, {"u", Value::OfUnsigned(7)}});
  EXPECT_EQ(m.Find("u")->kind, Value::Kind::Integer);  // fits int64
  EXPECT_EQ(m.Find("missing"), nullptr);
  EXPECT_EQ(Value::OfInteger(1).Find("k"), nullptr);  // not a map
  EXPECT_EQ(ValueJsonLine(m), R"({"k":["a","b"],"u":7})");
  EXPECT_EQ(ValueJsonLine(Value::OfUnsigned(9223372036854775808ULL)), "9223372036854775808");
}

}  // namespace
}  // namespace essaim
