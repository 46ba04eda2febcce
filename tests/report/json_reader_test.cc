#include "lvslam/report/json_reader.h"

#include <gtest/gtest.h>

#include "lvslam/core/error.h"
#include "support/temp_dir.h"

namespace lvslam::report {
namespace {

TEST(JsonReader, ReadsWhatTheJsonWriterWrites) {
  const nlohmann::json v = parseJson(R"({"a": [1, -2.5e1, true, null], "b": {"c": "x\"y\n"}})", "t.json");
  ASSERT_TRUE(v.is_object());
  ASSERT_EQ(findMember(v, "a")->size(), 4u);
  EXPECT_EQ(v["a"][1].get<double>(), -25.0);
  EXPECT_TRUE(v["a"][2].get<bool>());
  EXPECT_TRUE(v["a"][3].is_null());
  EXPECT_EQ(findMember(*findMember(v, "b"), "c")->get<std::string>(), "x\"y\n");
  EXPECT_EQ(findMember(v, "missing"), nullptr);
  EXPECT_EQ(findMember(v["a"], "a"), nullptr);  // not an object
}

TEST(JsonReader, ATruncatedFileNamesItselfAndTheByte) {
  const std::string message = testing::errorMessageOf([] { parseJson("{\"frames\": [{\"t\": 1}, {\"t\"", "stats.json"); });
  EXPECT_NE(message.find("stats.json: invalid JSON at byte 26"), std::string::npos) << message;
  EXPECT_NE(message.find("truncated"), std::string::npos) << message;
}

TEST(JsonReader, ACorruptByteIsNamed) {
  const std::string message = testing::errorMessageOf([] { parseJson("{\"a\": 1, \"b\": x}", "stats.json"); });
  EXPECT_NE(message.find("stats.json: invalid JSON at byte 14: "), std::string::npos) << message;
  EXPECT_EQ(message.find("truncated"), std::string::npos) << message;
  EXPECT_EQ(message.find("json.exception"), std::string::npos) << message;
}

// What the callback drops is still read: a corrupt byte inside it is
// refused as in a full parse, and what it keeps is whole.
TEST(JsonReader, WhatTheCallbackDropsIsCheckedNotKept) {
  const auto top_level_only = [](int depth, nlohmann::json::parse_event_t, nlohmann::json&) { return depth <= 1; };
  const nlohmann::json v = parseJson(R"({"s": 2, "frames": [{"t": 1}, {"t": 2}]})", "stats.json", top_level_only);
  EXPECT_EQ(v["s"].get<int>(), 2);
  ASSERT_NE(findMember(v, "frames"), nullptr);
  EXPECT_TRUE(findMember(v, "frames")->empty());
  const std::string message = testing::errorMessageOf(
      [&] { parseJson(R"({"s": 2, "frames": [{"t": 1}, {"t": x}]})", "stats.json", top_level_only); });
  EXPECT_NE(message.find("stats.json: invalid JSON at byte 36"), std::string::npos) << message;
}

TEST(JsonReader, CorruptTextIsRefused) {
  for (const char* text : {"{\"a\": 1,}", "[1 2]", "{\"a\": nul}", "{\"a\": 1} x", "{a: 1}", ""})
    EXPECT_NE(testing::errorMessageOf([&] { parseJson(text, "f.json"); }).find("f.json: invalid JSON"), std::string::npos)
        << text;
}

// A \u escape that is not four hexadecimal digits, or a lone surrogate, was
// std::stoul's std::invalid_argument in the hand-written reader (exit 1).
TEST(JsonReader, ABadUnicodeEscapeIsAnLvslamError) {
  for (const char* text : {"{\"a\": \"\\uZZZZ\"}", "{\"a\": \"\\u12\"}", "{\"a\": \"\\uD800\"}", "[\"\\u-1ab\"]"}) {
    try {
      parseJson(text, "s.json");
      ADD_FAILURE() << text << " was accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("s.json: invalid JSON at byte "), std::string::npos) << e.what();
    }
  }
}

TEST(JsonReader, InvalidUtf8IsAnLvslamError) {
  EXPECT_THROW(parseJson("{\"a\": \"\xff\xfe\"}", "u.json"), Error);
}

TEST(JsonReader, DeepNestingIsAnErrorNotACrash) {
  const std::string deep(100000, '[');
  const std::string message = testing::errorMessageOf([&] { parseJson(deep, "deep.json"); });
  EXPECT_NE(message.find("deep.json: invalid JSON at byte 100000: the file ends early"), std::string::npos) << message;
  // Closed, it is a document (read and destroyed without recursion).
  EXPECT_TRUE(parseJson(deep + std::string(100000, ']'), "deep.json").is_array());
}

TEST(JsonReader, AMissingFileIsNamed) {
  testing::TempDir dir;
  EXPECT_NE(testing::errorMessageOf([&] { readJsonFile(dir.file("none.json")); }).find("none.json"), std::string::npos);
}

}  // namespace
}  // namespace lvslam::report
