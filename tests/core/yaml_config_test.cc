#include "lvslam/core/yaml_config.h"

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
