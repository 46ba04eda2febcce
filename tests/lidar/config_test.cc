// The LiDAR configuration: the shipped preset loads; bad keys are named.
#include <gtest/gtest.h>

#include "support/temp_dir.h"
#include "lvslam/lidar/lidar_config.h"

namespace lvslam::lidar {
namespace {

LidarOdometryConfig fromText(const std::string& text) {
  return loadLidarOdometryConfig(YamlConfig::loadString(text, "test.yaml"));
}

TEST(LidarConfig, ShippedSimPresetEqualsTheDefaults) {
  const auto config = loadLidarOdometryConfig(YamlConfig::loadFile(LVSLAM_SOURCE_DIR "/config/sim.yaml"));
  const LidarOdometryConfig defaults;
  EXPECT_EQ(config.features.neighbours, defaults.features.neighbours);
  EXPECT_EQ(config.local_map.refined_rate_alpha, defaults.local_map.refined_rate_alpha);
  EXPECT_EQ(config.registration.min_inlier_ratio, defaults.registration.min_inlier_ratio);
  EXPECT_EQ(config.preprocess.voxel_size, defaults.preprocess.voxel_size);
}

TEST(LidarConfig, ReadsValuesAndNamesBadKeys) {
  EXPECT_EQ(fromText("lidar:\n  local_map:\n    refined_rate_alpha: 0.1\n").local_map.refined_rate_alpha, 0.1);
  EXPECT_EQ(fromText("other: 1\n").features.neighbours, LidarOdometryConfig{}.features.neighbours);
  using testing::errorMessageOf;
  EXPECT_NE(errorMessageOf([] { fromText("lidar:\n  features:\n    neighbors: 3\n"); }).find("lidar.features.neighbors"),
            std::string::npos);
  EXPECT_NE(errorMessageOf([] { fromText("lidar:\n  voxel: 1\n"); }).find("lidar.voxel"), std::string::npos);
  EXPECT_NE(errorMessageOf([] { fromText("lidar:\n  preprocess:\n    voxel_size: abc\n"); })
                .find("lidar.preprocess.voxel_size"),
            std::string::npos);
  EXPECT_NE(errorMessageOf([] { fromText("lidar:\n  local_map:\n    refined_rate_alpha: 1.5\n"); })
                .find("refined_rate_alpha"),
            std::string::npos);
}

}  // namespace
}  // namespace lvslam::lidar
