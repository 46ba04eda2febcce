#include "lvslam/fusion/fusion_config.h"

#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace lvslam::fusion {
namespace {

using lvslam::testing::errorMessageOf;

TEST(FusionConfig, AbsentSectionKeepsTheDefaults) {
  const FusionConfig c = loadFusionConfig(YamlConfig::loadString("lidar: {}\n", "x.yaml"));
  EXPECT_EQ(c.min_neighbours, FusionConfig{}.min_neighbours);
  EXPECT_EQ(c.max_neighbour_angle_deg, FusionConfig{}.max_neighbour_angle_deg);
}

TEST(FusionConfig, ReadsEveryKeyGiven) {
  const FusionConfig c = loadFusionConfig(
      YamlConfig::loadString("fusion:\n  min_neighbours: 11\n  arc_step_deg: 0.5\n  max_depth: 30\n", "x.yaml"));
  EXPECT_EQ(c.min_neighbours, 11);
  EXPECT_DOUBLE_EQ(c.arc_step_deg, 0.5);
  EXPECT_DOUBLE_EQ(c.max_depth, 30.0);
}

TEST(FusionConfig, BadKeysAndValuesAreErrorsNamingFileAndKey) {
  const std::string unknown =
      errorMessageOf([] { loadFusionConfig(YamlConfig::loadString("fusion:\n  min_neighbors: 3\n", "f.yaml")); });
  EXPECT_NE(unknown.find("f.yaml"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("fusion.min_neighbors"), std::string::npos) << unknown;
  const std::string range =
      errorMessageOf([] { loadFusionConfig(YamlConfig::loadString("fusion:\n  min_matched_ratio: 1.5\n", "f.yaml")); });
  EXPECT_NE(range.find("fusion.min_matched_ratio"), std::string::npos) << range;
  const std::string type =
      errorMessageOf([] { loadFusionConfig(YamlConfig::loadString("fusion:\n  min_neighbours: many\n", "f.yaml")); });
  EXPECT_NE(type.find("fusion.min_neighbours"), std::string::npos) << type;
  EXPECT_NE(errorMessageOf([] { loadFusionConfig(YamlConfig::loadString("fusion: 3\n", "f.yaml")); }), "");
}

TEST(FusionConfig, SimYamlRepeatsTheDefaults) {
  const FusionConfig c = loadFusionConfig(YamlConfig::loadFile(LVSLAM_SOURCE_DIR "/config/sim.yaml"));
  const FusionConfig d;
  EXPECT_EQ(c.min_neighbours, d.min_neighbours);
  EXPECT_DOUBLE_EQ(c.max_neighbour_angle_deg, d.max_neighbour_angle_deg);
  EXPECT_DOUBLE_EQ(c.min_matched_ratio, d.min_matched_ratio);
  EXPECT_DOUBLE_EQ(c.min_plane_angle_deg, d.min_plane_angle_deg);
  EXPECT_DOUBLE_EQ(c.arc_step_deg, d.arc_step_deg);
  EXPECT_EQ(c.accumulated_scans, d.accumulated_scans);
}

}  // namespace
}  // namespace lvslam::fusion
