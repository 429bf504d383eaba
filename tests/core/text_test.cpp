// core's text, path and JSON helpers against hand-computed values.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "core/json.h"
#include "core/paths.h"
#include "core/strings.h"

namespace essaim {

TEST(FormatDouble, ShortestTextThatReadsBack) {
  EXPECT_EQ(FormatDouble(0), "0");
  EXPECT_EQ(FormatDouble(-0.0), "-0");
  EXPECT_EQ(FormatDouble(100), "100");
  EXPECT_EQ(FormatDouble(123456789012345.0), "123456789012345");
  EXPECT_EQ(FormatDouble(1e15), "1e+15");
  EXPECT_EQ(FormatDouble(0.1), "0.1");
  EXPECT_EQ(FormatDouble(1.0 / 3), "0.3333333333333333");
  EXPECT_EQ(FormatDouble(0.0001), "0.0001");
  EXPECT_EQ(FormatDouble(0.00001234), "1.234e-05");
  EXPECT_EQ(FormatDouble(1.5e7 + 0.5), "15000000.5");
  EXPECT_EQ(FormatDouble(7.186127289416615e16), "7.186127289416615e+16");
  EXPECT_EQ(FormatDouble(5e-324), "5e-324");
}

TEST(Paths, JoinAndDirName) {
  EXPECT_EQ(JoinPath("a/b", "c.lua"), "a/b/c.lua");
  EXPECT_EQ(JoinPath("a/b/", "c.lua"), "a/b/c.lua");
  EXPECT_EQ(JoinPath("", "c.lua"), "c.lua");
  EXPECT_EQ(JoinPath("a", "/abs/c.lua"), "/abs/c.lua");
  EXPECT_EQ(JoinPath("dossier été", "../x.png"), "dossier été/../x.png");
  EXPECT_EQ(DirName("a/b/c.argos"), "a/b");
  EXPECT_EQ(DirName("c.argos"), "");
  EXPECT_EQ(DirName("/c.argos"), "/");
  // As std::filesystem's parent_path(), which DirName no longer calls.
  for (const char* p :
       {"a//b", "a/b/", "a/b//", "//c", "///c", "/", "//", "", ".", "a/..", "./x", "/a/", "//a/b", "dossier été/x.lua"})
    EXPECT_EQ(DirName(p), std::filesystem::path(p).parent_path().string()) << p;
}

TEST(Paths, AFolderIsNotAFile) {
  std::string dir = std::filesystem::temp_directory_path().string();
  std::string text = "untouched";
  EXPECT_FALSE(FileExists(dir));
  EXPECT_FALSE(ReadFile(dir, &text));
  EXPECT_EQ(text, "untouched");
  EXPECT_FALSE(ReadFile(dir + "/no such file", &text));
}

TEST(Json, OrderedIndentedAndNonFiniteAsNull) {
  Json doc = Json::object();
  doc["z"] = 1;
  doc["a"] = std::numeric_limits<double>::quiet_NaN();
  doc["list"] = Json::array({0.1, -HUGE_VAL});
  EXPECT_EQ(DumpJson(doc), "{\n  \"z\": 1,\n  \"a\": null,\n  \"list\": [\n    0.1,\n    null\n  ]\n}\n");
}

TEST(Json, NulAndControlCharactersEscaped) {
  Json doc = Json::object();
  doc[std::string("a\0b", 3)] = std::string("x\ny\0", 4);
  EXPECT_EQ(DumpJson(doc), "{\n  \"a\\u0000b\": \"x\\ny\\u0000\"\n}\n");
}

TEST(Json, ParseErrorsSayWhere) {
  Json doc;
  std::string error;
  EXPECT_FALSE(ParseJson("{\"a\": 1,\n }", &doc, &error));
  EXPECT_NE(error.find("invalid JSON at line 2, column 2"), std::string::npos) << error;
  ASSERT_TRUE(ParseJson("{\"b\": 2.5, \"a\": 9007199254740993}", &doc, &error));
  EXPECT_EQ(doc.begin().key(), "b");
  EXPECT_EQ(doc["a"].get<int64_t>(), 9007199254740993);
}

}  // namespace essaim
