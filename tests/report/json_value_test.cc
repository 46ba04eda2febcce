#include "lvslam/report/json_value.h"

#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace lvslam::report {
namespace {

TEST(JsonValue, ReadsWhatTheJsonWriterWrites) {
  const JsonValue v = parseJson(R"({"a": [1, -2.5e1, true, null], "b": {"c": "x\"y\n"}})", "t.json");
  ASSERT_TRUE(v.isObject());
  ASSERT_EQ(v.find("a")->array.size(), 4u);
  EXPECT_EQ(v.find("a")->array[1].number, -25.0);
  EXPECT_TRUE(v.find("a")->array[2].boolean);
  EXPECT_EQ(v.find("a")->array[3].type, JsonValue::Type::kNull);
  EXPECT_EQ(v.find("b")->find("c")->string, "x\"y\n");
  EXPECT_EQ(v.find("missing"), nullptr);
}

TEST(JsonValue, ATruncatedFileNamesItselfAndTheByte) {
  const std::string message = testing::errorMessageOf([] { parseJson("{\"frames\": [{\"t\": 1}, {\"t\"", "stats.json"); });
  EXPECT_NE(message.find("stats.json: invalid JSON at byte 26"), std::string::npos) << message;
  EXPECT_NE(message.find("truncated"), std::string::npos) << message;
}

TEST(JsonValue, CorruptTextIsRefused) {
  for (const char* text : {"{\"a\": 1,}", "[1 2]", "{\"a\": nul}", "{\"a\": 1} x", "{a: 1}", ""})
    EXPECT_NE(testing::errorMessageOf([&] { parseJson(text, "f.json"); }).find("f.json: invalid JSON"), std::string::npos)
        << text;
}

TEST(JsonValue, DeepNestingIsAnErrorNotACrash) {
  const std::string deep(100000, '[');
  EXPECT_NE(testing::errorMessageOf([&] { parseJson(deep, "deep.json"); }).find("nested too deeply"), std::string::npos);
}

TEST(JsonValue, AMissingFileIsNamed) {
  testing::TempDir dir;
  EXPECT_NE(testing::errorMessageOf([&] { readJsonFile(dir.file("none.json")); }).find("none.json"), std::string::npos);
}

}  // namespace
}  // namespace lvslam::report
