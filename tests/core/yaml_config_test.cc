#include "lvslam/core/yaml_config.h"

#include <filesystem>

#include <gtest/gtest.h>

#include "lvslam/core/error.h"
#include "support/temp_dir.h"

namespace lvslam {
namespace {

TEST(YamlConfig, ReadsNestedValues) {
  const YamlConfig c = YamlConfig::loadString("a:\n  b: 2.5\n  list: [1, 2, 3]\n  flag: true\n", "cfg.yaml");
  EXPECT_DOUBLE_EQ(c.at("a").at("b").asDouble(), 2.5);
  EXPECT_EQ(c.at("a").at("list").asDoubles(), (std::vector<double>{1, 2, 3}));
  EXPECT_TRUE(c.at("a").getBool("flag", false));
  EXPECT_EQ(c.at("a").getInt("missing", 7), 7);
}

TEST(YamlConfig, MissingKeyNamesFileAndFullKeyPath) {
  const YamlConfig c = YamlConfig::loadString("camera:\n  width: 640\n", "seq/sequence.yaml");
  const std::string msg = testing::errorMessageOf([&] { c.at("camera").at("height"); });
  EXPECT_NE(msg.find("seq/sequence.yaml"), std::string::npos) << msg;
  EXPECT_NE(msg.find("camera.height"), std::string::npos) << msg;
}

TEST(YamlConfig, MalformedNumberNamesTheKeyAndTheValue) {
  const YamlConfig c = YamlConfig::loadString("k: [1.0, abc]\n", "x.yaml");
  const std::string msg = testing::errorMessageOf([&] { c.at("k").asDoubles(); });
  EXPECT_NE(msg.find("k[1]"), std::string::npos) << msg;
  EXPECT_NE(msg.find("abc"), std::string::npos) << msg;
  const YamlConfig n = YamlConfig::loadString("v: .nan\n", "x.yaml");
  EXPECT_FALSE(testing::errorMessageOf([&] { n.at("v").asDouble(); }).empty());
}

TEST(YamlConfig, NonScalarKeyNamesFileLineAndKeyPath) {
  // A list or a mapping as a key was yaml-cpp's "bad conversion" later on,
  // with no file named; anywhere in the document it is refused on loading.
  for (const char* text : {"system:\n  ? [a, b]\n  : 1\n", "system:\n  {a: 1}: 2\n",
                           "list:\n  - ok: 1\n  - ? [x]\n    : 2\n"}) {
    const std::string msg = testing::errorMessageOf([&] { YamlConfig::loadString(text, "cfg.yaml"); });
    EXPECT_NE(msg.find("cfg.yaml:"), std::string::npos) << text << " -> " << msg;
    EXPECT_NE(msg.find("plain name"), std::string::npos) << msg;
  }
  const std::string msg =
      testing::errorMessageOf([] { YamlConfig::loadString("system:\n  fine: 1\n  ? [a, b]\n  : 1\n", "c.yaml"); });
  EXPECT_NE(msg.find("c.yaml:3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("key 'system'"), std::string::npos) << msg;
}

TEST(YamlConfig, LoadFileNamesAFolderAndAMissingFile) {
  testing::TempDir dir;
  std::filesystem::create_directories(dir.file("a_folder"));
  std::string msg = testing::errorMessageOf([&] { YamlConfig::loadFile(dir.file("a_folder")); });
  EXPECT_NE(msg.find("a_folder: is a folder"), std::string::npos) << msg;
  msg = testing::errorMessageOf([&] { YamlConfig::loadFile(dir.file("none.yaml")); });
  EXPECT_NE(msg.find("none.yaml: file not found"), std::string::npos) << msg;
}

TEST(YamlConfig, MalformedYamlNamesFileAndLine) {
  const std::string msg = testing::errorMessageOf([] { YamlConfig::loadString("a: [1, 2\nb: 3\n", "broken.yaml"); });
  EXPECT_NE(msg.find("broken.yaml"), std::string::npos) << msg;
  EXPECT_NE(msg.find("line"), std::string::npos) << msg;
}

TEST(YamlConfig, MissingFileIsAnError) {
  EXPECT_NE(testing::errorMessageOf([] { YamlConfig::loadFile("/nonexistent/cfg.yaml"); }).find("/nonexistent/cfg.yaml"),
            std::string::npos);
}

}  // namespace
}  // namespace lvslam
