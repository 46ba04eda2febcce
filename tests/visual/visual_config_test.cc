#include "lvslam/visual/visual_config.h"

#include <gtest/gtest.h>

#include "lvslam/core/error.h"
#include "lvslam/visual/visual_slam.h"
#include "support/temp_dir.h"

namespace lvslam::visual {
namespace {

VisualSlamConfig loadSlam(const std::string& text) {
  return loadSection<VisualSlamConfig>(YamlConfig::loadString(text, "test.yaml"), "visual");
}
VisualConfig load(const std::string& text) { return loadSlam(text).modules; }

// The text fails to load with a message that names `key`.
void expectErrorNaming(const std::string& text, const std::string& key) {
  const std::string message = lvslam::testing::errorMessageOf([&] { load(text); });
  EXPECT_NE(message.find(key), std::string::npos) << message;
}

TEST(VisualConfig, AbsentKeysKeepDefaultsAndPresentOnesOverride) {
  const VisualConfig defaults = load("visual: {}\n");
  EXPECT_EQ(defaults.features.orb.max_features, OrbExtractorConfig{}.max_features);
  const VisualConfig c = load(
      "visual:\n"
      "  orb: {max_features: 800, num_levels: 6, candidate_factor: 4}\n"
      "  lines: {enabled: false, min_length_ratio: 0.1}\n"
      "  pose: {rounds: 3}\n"
      "  bundle_adjustment: {window_size: 7, direction_weight: 200.0}\n"
      "  initializer: {min_parallax_deg: 2.0}\n");
  EXPECT_EQ(c.features.orb.max_features, 800);
  EXPECT_EQ(c.features.orb.num_levels, 6);
  EXPECT_EQ(c.features.orb.candidate_factor, 4.0);
  EXPECT_FALSE(c.features.extract_lines);
  EXPECT_DOUBLE_EQ(c.features.lines.min_length_ratio, 0.1);
  EXPECT_EQ(c.pose.rounds, 3);
  EXPECT_EQ(c.local_window.window_size, 7u);
  EXPECT_DOUBLE_EQ(c.local_window.ba.direction_weight, 200.0);
  EXPECT_DOUBLE_EQ(c.initializer.min_parallax_deg, 2.0);
}

TEST(VisualConfig, KeypointDepthSection) {
  EXPECT_TRUE(load("visual: {}\n").use_keypoint_depths);
  const VisualConfig c = load("visual:\n  keypoint_depths: {sigma_ratio: 0.05, huber_delta: 1.5, chi2: 2.7}\n");
  EXPECT_DOUBLE_EQ(c.local_window.ba.depth_sigma_ratio, 0.05);
  EXPECT_DOUBLE_EQ(c.local_window.ba.depth_huber_delta, 1.5);
  EXPECT_DOUBLE_EQ(c.local_window.ba.chi2_depth, 2.7);
  expectErrorNaming("visual:\n  keypoint_depths: {sigma_ratio: 0.0}\n", "keypoint_depths");
  EXPECT_THROW(load("visual:\n  keypoint_depths: {sigma: 0.02}\n"), Error);
}

TEST(VisualConfig, LidarPosePriorSection) {
  EXPECT_TRUE(load("visual: {}\n").use_lidar_pose_priors);  // fused mode alone gives the poses
  EXPECT_FALSE(load("visual:\n  lidar_pose_priors: {enabled: false}\n").use_lidar_pose_priors);
  const VisualConfig c =
      load("visual:\n  lidar_pose_priors: {enabled: true, sigma_m: 0.02, sigma_deg: 0.5, huber_delta: 2.0}\n");
  EXPECT_TRUE(c.use_lidar_pose_priors);
  EXPECT_DOUBLE_EQ(c.local_window.ba.prior_sigma_m, 0.02);
  EXPECT_DOUBLE_EQ(c.local_window.ba.prior_sigma_deg, 0.5);
  EXPECT_DOUBLE_EQ(c.local_window.ba.prior_huber_delta, 2.0);
  expectErrorNaming("visual:\n  lidar_pose_priors: {sigma_deg: -1}\n", "lidar_pose_priors");
  EXPECT_THROW(load("visual:\n  lidar_pose_priors: {sigma: 0.02}\n"), Error);
}

// The map correction runs with the priors; its pose graph takes local BA's
// prior sigmas, so one number means the same in both.
TEST(VisualConfig, MapCorrectionUnderTheLidarPosePriors) {
  const VisualConfig d = load("visual: {}\n");
  EXPECT_EQ(d.map_correction.every_keyframes, MapCorrectionConfig{}.every_keyframes);
  EXPECT_DOUBLE_EQ(d.map_correction.graph.prior_sigma_m, d.local_window.ba.prior_sigma_m);
  const VisualConfig c = load(
      "visual:\n  lidar_pose_priors:\n    sigma_m: 0.03\n    sigma_deg: 0.4\n"
      "    map_correction: {every_keyframes: 5, window_keyframes: 40, min_covisibility: 20, sigma_m: 0.01,\n"
      "                     sigma_deg: 0.2, iterations: 4}\n");
  EXPECT_EQ(c.map_correction.every_keyframes, 5);
  EXPECT_EQ(c.map_correction.window_keyframes, 40);
  EXPECT_EQ(c.map_correction.min_covisibility, 20);
  EXPECT_DOUBLE_EQ(c.map_correction.graph.edge_sigma_m, 0.01);
  EXPECT_DOUBLE_EQ(c.map_correction.graph.edge_sigma_deg, 0.2);
  EXPECT_EQ(c.map_correction.graph.max_iterations, 4);
  EXPECT_DOUBLE_EQ(c.map_correction.graph.prior_sigma_m, 0.03);
  EXPECT_DOUBLE_EQ(c.map_correction.graph.prior_sigma_deg, 0.4);
  EXPECT_EQ(load("visual:\n  lidar_pose_priors: {map_correction: {every_keyframes: 0}}\n").map_correction.every_keyframes,
            0);  // off
  expectErrorNaming("visual:\n  lidar_pose_priors: {map_correction: {sigma_m: 0}}\n", "map_correction");
  EXPECT_THROW(load("visual:\n  lidar_pose_priors: {map_correction: {every_keyframes: -1}}\n"), Error);
  EXPECT_EQ(load("visual:\n  lidar_pose_priors: {map_correction: {window_keyframes: 0}}\n").map_correction.window_keyframes,
            0);  // the whole map
  expectErrorNaming("visual:\n  lidar_pose_priors: {map_correction: {window_keyframes: -5}}\n", "map_correction");
  EXPECT_THROW(load("visual:\n  lidar_pose_priors: {map_correction: {every: 3}}\n"), Error);
}

TEST(VisualConfig, MapReuseSection) {
  const LocalKeyframeConfig defaults;
  EXPECT_DOUBLE_EQ(load("visual: {}\n").local_map.nearby_radius_depths, defaults.nearby_radius_depths);
  const VisualConfig c = load(
      "visual:\n  map_reuse: {radius_depths: 0.5, max_angle_deg: 20, max_keyframes: 3, min_age_keyframes: 7}\n");
  EXPECT_DOUBLE_EQ(c.local_map.nearby_radius_depths, 0.5);
  EXPECT_DOUBLE_EQ(c.local_map.nearby_max_angle_deg, 20.0);
  EXPECT_EQ(c.local_map.nearby_max, 3u);
  EXPECT_EQ(c.local_map.nearby_min_age, 7u);
  EXPECT_DOUBLE_EQ(load("visual:\n  map_reuse: {radius_depths: 0}\n").local_map.nearby_radius_depths, 0.0);  // off
  expectErrorNaming("visual:\n  map_reuse: {max_angle_deg: 0}\n", "map_reuse");
  EXPECT_THROW(load("visual:\n  map_reuse: {radius_depths: -1}\n"), Error);
  EXPECT_THROW(load("visual:\n  map_reuse: {max_keyframes: -2}\n"), Error);
  EXPECT_THROW(load("visual:\n  map_reuse: {radius: 1}\n"), Error);
}

TEST(VisualConfig, KeyframesSection) {
  const KeyframePolicy defaults;
  EXPECT_EQ(load("visual: {}\n").keyframes.max_interval, defaults.max_interval);
  const VisualConfig c = load(
      "visual:\n  keyframes: {tracked_ratio: 0.8, min_tracked: 60, min_interval: 6, max_interval: 10, "
      "min_inliers: 30}\n");
  EXPECT_DOUBLE_EQ(c.keyframes.tracked_ratio, 0.8);
  EXPECT_EQ(c.keyframes.min_tracked, 60);
  EXPECT_EQ(c.keyframes.min_interval, 6);
  EXPECT_EQ(c.keyframes.max_interval, 10);
  EXPECT_EQ(c.keyframes.min_inliers, 30);
  expectErrorNaming("visual:\n  keyframes: {tracked_ratio: 1.5}\n", "tracked_ratio");
  expectErrorNaming("visual:\n  keyframes: {tracked_ratio: 0}\n", "tracked_ratio");
  expectErrorNaming("visual:\n  keyframes: {min_tracked: -1}\n", "min_tracked");
  expectErrorNaming("visual:\n  keyframes: {min_interval: 6, max_interval: 4}\n", "min_interval");
  expectErrorNaming("visual:\n  keyframes: {min_interval: 0}\n", "min_interval");
  expectErrorNaming("visual:\n  keyframes: {max_intervall: 4}\n", "max_intervall");
}

// Switching off one of the contributions is --ablate's (direction-residual,
// keypoint-depths), not a file's.
TEST(VisualConfig, AblationSwitchesAreNotKeys) {
  expectErrorNaming("visual:\n  bundle_adjustment: {use_direction_residual: false}\n",
                    "visual.bundle_adjustment.use_direction_residual");
  expectErrorNaming("visual:\n  keypoint_depths: {enabled: false}\n", "visual.keypoint_depths.enabled");
}

// The settings of VisualSlamConfig itself, beside the algorithms' own.
TEST(VisualConfig, TrackingAndMappingSections) {
  const VisualSlamConfig d;
  const VisualSlamConfig c = loadSlam(
      "visual:\n"
      "  usability: {min_keypoints: 80, min_brightness: 12}\n"
      "  initializer: {window_px: 90, min_matches: 60, max_frames: 20, sigma_px: 1.5}\n"
      "  tracking: {search_radius_px: 12, min_tracked: 25, lidar_pose_buffer: 32, max_descriptor_distance: 64}\n"
      "  relocalization: {frames: 10, candidates: 3, min_inliers: 40}\n"
      "  point_matching: {check_orientation: false}\n"
      "  line_matching: {max_offset_px: 50}\n"
      "  local_keyframes: {max_voted: 15}\n"
      "  triangulation: {chi2_epipolar: 3.0, max_depth_points: 50}\n"
      "  culling: {min_found_ratio: 0.3}\n"
      "  line_depth_check: {fusion_ratio: 0.25}\n"
      "  bundle_adjustment: {fixed_oldest: 3}\n");
  EXPECT_EQ(c.min_keypoints, 80);
  EXPECT_DOUBLE_EQ(c.usability.min_brightness, 12.0);
  EXPECT_DOUBLE_EQ(c.usability.max_brightness, d.usability.max_brightness);
  EXPECT_DOUBLE_EQ(c.init_window_px, 90.0);
  EXPECT_EQ(c.min_init_matches, 60);
  EXPECT_EQ(c.max_init_frames, 20);
  EXPECT_DOUBLE_EQ(c.modules.initializer.sigma_px, 1.5);
  EXPECT_DOUBLE_EQ(c.search_radius_px, 12.0);
  EXPECT_EQ(c.min_tracked, 25);
  EXPECT_EQ(c.track_max_distance, 64);
  EXPECT_EQ(c.lidar_pose_buffer, 32u);
  EXPECT_EQ(c.relocalize_frames, 10);
  EXPECT_EQ(c.relocalize_candidates, 3u);
  EXPECT_EQ(c.relocalize_min_inliers, 40);
  EXPECT_FALSE(c.modules.point_matching.check_orientation);
  EXPECT_DOUBLE_EQ(c.modules.line_matching.max_offset_px, 50.0);
  EXPECT_EQ(c.modules.local_map.max_voted, 15u);
  EXPECT_DOUBLE_EQ(c.triangulation.chi2_epipolar, 3.0);
  EXPECT_EQ(c.triangulation.max_depth_points, 50);
  EXPECT_DOUBLE_EQ(c.culling.min_found_ratio, 0.3);
  EXPECT_DOUBLE_EQ(c.depth_check.fusion_ratio, 0.25);
  EXPECT_EQ(c.modules.local_window.fixed_oldest, 3);
  expectErrorNaming("visual:\n  tracking: {search_radius_px: 0}\n", "visual.tracking.search_radius_px");
  expectErrorNaming("visual:\n  tracking: {max_descriptor_distance: 257}\n", "visual.tracking.max_descriptor_distance");
  expectErrorNaming("visual:\n  usability: {min_brightness: 250}\n", "visual.usability.min_brightness");
  expectErrorNaming("visual:\n  relocalization: {candidates: -1}\n", "visual.relocalization.candidates");
  expectErrorNaming("visual:\n  triangulation: {create_depth_points: true}\n", "create_depth_points");  // the mode's
}

TEST(VisualConfig, BadValuesAndUnknownKeysNameTheKey) {
  const std::string typo = lvslam::testing::errorMessageOf([] { load("visual:\n  orb: {max_featurs: 10}\n"); });
  EXPECT_NE(typo.find("max_featurs"), std::string::npos) << typo;
  EXPECT_NE(typo.find("test.yaml"), std::string::npos) << typo;
  EXPECT_THROW(load("visual:\n  orb: {scale_factor: 0.9}\n"), Error);
  EXPECT_THROW(load("visual:\n  orb: {candidate_factor: 0.5}\n"), Error);
  EXPECT_THROW(load("visual:\n  lines: {scale: 2.0}\n"), Error);
  EXPECT_THROW(load("visual:\n  bundle_adjustment: {window_size: 1}\n"), Error);
  EXPECT_THROW(load("visual:\n  pose: {rounds: 0}\n"), Error);
  EXPECT_THROW(load("visual:\n  orb: {max_features: abc}\n"), Error);
  EXPECT_THROW(load("visual: 3\n"), Error);
  const std::string orb = lvslam::testing::errorMessageOf([] { load("visual:\n  orb: {scale_factor: 0.9}\n"); });
  EXPECT_NE(orb.find("test.yaml: key 'visual.orb': scale_factor"), std::string::npos) << orb;
}

}  // namespace
}  // namespace lvslam::visual
