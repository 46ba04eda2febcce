// The shipped configuration files against the key tables: config/advanced.yaml
// holds every key with exactly the built-in default, every key reaches its own
// member, and a bad value or an unknown key is named with its file.
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "lvslam/core/error.h"
#include "lvslam/system/system_config.h"
#include "support/temp_dir.h"

namespace lvslam::system {
namespace {

using lvslam::testing::errorMessageOf;

const std::string kAdvanced = std::string(LVSLAM_SOURCE_DIR) + "/config/advanced.yaml";
const std::string kSim = std::string(LVSLAM_SOURCE_DIR) + "/config/sim.yaml";

// Every key with its value as text.
std::map<std::string, std::string> values(SystemConfig& config) {
  const ConfigKeys keys = configKeys(config);
  std::map<std::string, std::string> out;
  for (const std::string& key : keys.keys()) out[key] = keys.text(key);
  return out;
}

void collectLeaves(const YAML::Node& node, const std::string& prefix, std::set<std::string>& out) {
  for (const auto& item : node) {
    const std::string key = prefix.empty() ? item.first.Scalar() : prefix + "." + item.first.Scalar();
    if (item.second.IsMap())
      collectLeaves(item.second, key, out);
    else
      out.insert(key);
  }
}

// "a.b.c" and "v" as "a: {b: {c: v}}".
std::string yamlOf(const std::string& key, const std::string& value) {
  std::string text = value;
  std::string rest = key;
  for (std::size_t dot = rest.rfind('.'); dot != std::string::npos; dot = rest.rfind('.')) {
    text = fmt::format("{{{}: {}}}", rest.substr(dot + 1), text);
    rest = rest.substr(0, dot);
  }
  return fmt::format("{}: {}\n", rest, text);
}

// Another value of the same type as `text`.
std::string otherValue(const std::string& text) {
  if (text == "true") return "false";
  if (text == "false") return "true";
  if (text == "scans") return "features";
  if (text == "features") return "scans";
  if (text.find_first_of(".e") == std::string::npos) return std::to_string(std::stol(text) + 1);
  return fmt::format("{}", std::stod(text) + 1.0);
}

TEST(ConfigFiles, AdvancedYamlHasEveryKeyAndNoOther) {
  SystemConfig defaults;
  const std::map<std::string, std::string> keys = values(defaults);
  std::set<std::string> leaves;
  collectLeaves(YamlConfig::loadFile(kAdvanced).node(), "", leaves);
  for (const auto& [key, text] : keys) EXPECT_TRUE(leaves.count(key)) << key << " is missing from advanced.yaml";
  for (const std::string& leaf : leaves) EXPECT_TRUE(keys.count(leaf)) << leaf << " is no key";
}

// So that a binary which cannot see the file runs the same as one that reads it.
TEST(ConfigFiles, AdvancedYamlHoldsTheBuiltInDefaults) {
  SystemConfig defaults;
  SystemConfig advanced = loadSystemConfig(YamlConfig::loadFile(kAdvanced));
  const std::map<std::string, std::string> expected = values(defaults), loaded = values(advanced);
  for (const auto& [key, text] : expected) EXPECT_EQ(loaded.at(key), text) << key;
}

// sim.yaml shows a few keys; runs with it are runs with the defaults.
TEST(ConfigFiles, SimYamlRepeatsTheDefaults) {
  SystemConfig defaults;
  SystemConfig sim = loadSystemConfig(YamlConfig::loadFile(kSim));
  const std::map<std::string, std::string> expected = values(defaults), loaded = values(sim);
  for (const auto& [key, text] : expected) EXPECT_EQ(loaded.at(key), text) << key;
}

TEST(ConfigFiles, RunsReadAdvancedYamlFromTheSourceTree) {
  EXPECT_EQ(advancedConfigPath(), kAdvanced);
  SystemConfig defaults;
  SystemConfig run = loadRunConfig("");
  EXPECT_EQ(values(run), values(defaults));
  lvslam::testing::TempDir dir;
  dir.write("user.yaml", "lidar:\n  preprocess:\n    max_range: 40\n");
  EXPECT_DOUBLE_EQ(loadRunConfig(dir.file("user.yaml")).lidar.preprocess.max_range, 40.0);
  dir.write("bad.yaml", "lidar:\n  preprocess:\n    min_range: 70\n");  // beyond advanced.yaml's max_range
  const std::string message = errorMessageOf([&] { loadRunConfig(dir.file("bad.yaml")); });
  EXPECT_EQ(message.rfind(dir.file("bad.yaml") + ": key 'lidar.preprocess.min_range'", 0), 0u) << message;
}

// Each key changes its own member and no other (no two keys share one, no
// key is bound to nothing).
TEST(ConfigFiles, EveryKeyIsReadIntoItsOwnMember) {
  SystemConfig defaults;
  const std::map<std::string, std::string> before = values(defaults);
  for (const auto& [key, text] : before) {
    SystemConfig config;
    const std::string value = otherValue(text);
    configKeys(config).read(YamlConfig::loadString(yamlOf(key, value), "test.yaml"));
    const std::map<std::string, std::string> after = values(config);
    for (const auto& [other, other_text] : after)
      EXPECT_EQ(other_text == before.at(other), other != key) << key << " = " << value << " changed " << other;
  }
}

void readValue(const std::string& key, const std::string& value) {
  SystemConfig config;
  readSystemConfig(config, YamlConfig::loadString(yamlOf(key, value), "test.yaml"));
}

TEST(ConfigFiles, AMalformedValueNamesFileAndKey) {
  SystemConfig defaults;
  for (const auto& [key, text] : values(defaults)) {
    for (const std::string bad : {"abc", "[1, 2]", "{a: 1}"}) {
      const std::string message = errorMessageOf([&] { readValue(key, bad); });
      EXPECT_EQ(message.rfind("test.yaml: key '" + key + "': ", 0), 0u) << key << " = " << bad << ": " << message;
    }
  }
}

TEST(ConfigFiles, AnUnknownKeyNamesFileAndKey) {
  lvslam::testing::TempDir dir;
  // The key written, and the first part of it that is unknown.
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"lidar.preprocess.voxel_sise", "lidar.preprocess.voxel_sise"},
      {"visual.lidar_pose_priors.map_correction.every", "visual.lidar_pose_priors.map_correction.every"},
      {"estimator.window", "estimator.window"},
      {"system.fusion_lines_in_tracking", "system.fusion_lines_in_tracking"},
      {"visual.orbs.max_features", "visual.orbs"},
      {"loops", "loops"}};
  for (const auto& [key, unknown] : cases) {
    dir.write("user.yaml", yamlOf(key, "1"));
    const std::string message = errorMessageOf([&] { loadRunConfig(dir.file("user.yaml")); });
    EXPECT_EQ(message, dir.file("user.yaml") + ": key '" + unknown + "': unknown key (config/advanced.yaml lists every key)");
  }
}

}  // namespace
}  // namespace lvslam::system
