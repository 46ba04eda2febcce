#include "lvslam/system/system_config.h"

#include <gtest/gtest.h>

#include "lvslam/core/error.h"
#include "support/temp_dir.h"

namespace lvslam::system {
namespace {

using lvslam::testing::errorMessageOf;

SystemConfig load(const std::string& text) { return loadSystemConfig(YamlConfig::loadString(text, "test.yaml")); }

TEST(SystemConfig, EmptyFileKeepsEveryDefault) {
  const SystemConfig c = load("{}");
  const SystemConfig d;
  EXPECT_EQ(c.mode, RunMode::kFused);
  EXPECT_FALSE(c.deterministic);
  EXPECT_EQ(c.detection.frames_to_recover, d.detection.frames_to_recover);
  EXPECT_EQ(c.lidar.preprocess.voxel_size, d.lidar.preprocess.voxel_size);
  EXPECT_EQ(c.fusion.arc_step_deg, d.fusion.arc_step_deg);
  EXPECT_EQ(c.map_voxel, d.map_voxel);
  EXPECT_TRUE(c.final_map_poses);
  EXPECT_TRUE(c.final_map_relocation);
}

TEST(SystemConfig, ReadsEverySection) {
  const SystemConfig c = load(
      "lidar:\n"
      "  preprocess:\n"
      "    voxel_size: 0.4\n"
      "visual:\n"
      "  orb:\n"
      "    max_features: 543\n"
      "fusion:\n"
      "  arc_step_deg: 0.35\n"
      "detection:\n"
      "  min_tracked_points: 17\n"
      "  min_tracked_lines: 3\n"
      "  min_inlier_ratio: 0.25\n"
      "  min_brightness: 12\n"
      "  max_brightness: 230\n"
      "  min_contrast: 4.5\n"
      "  frames_to_recover: 6\n"
      "  rejoin_step_m: 0.004\n"
      "  rejoin_step_deg: 0.1\n"
      "system:\n"
      "  depth_hint_max_dt: 0.04\n"
      "  keypoint_depth_max_dt: 0.07\n"
      "  keypoint_depth_source: features\n"
      "  map_voxel: 0.3\n"
      "  final_map_poses: false\n"
      "  final_map_relocation: false\n");
  EXPECT_FALSE(c.final_map_poses);
  EXPECT_FALSE(c.final_map_relocation);
  EXPECT_DOUBLE_EQ(c.lidar.preprocess.voxel_size, 0.4);
  EXPECT_EQ(c.visual.modules.features.orb.max_features, 543);
  EXPECT_DOUBLE_EQ(c.fusion.arc_step_deg, 0.35);
  EXPECT_EQ(c.detection.min_tracked_points, 17);
  EXPECT_EQ(c.detection.min_tracked_lines, 3);
  EXPECT_DOUBLE_EQ(c.detection.min_inlier_ratio, 0.25);
  EXPECT_DOUBLE_EQ(c.detection.min_brightness, 12.0);
  EXPECT_DOUBLE_EQ(c.detection.max_brightness, 230.0);
  EXPECT_DOUBLE_EQ(c.detection.min_contrast, 4.5);
  EXPECT_EQ(c.detection.frames_to_recover, 6);
  EXPECT_DOUBLE_EQ(c.detection.rejoin_step_m, 0.004);
  EXPECT_DOUBLE_EQ(c.detection.rejoin_step_deg, 0.1);
  EXPECT_DOUBLE_EQ(c.depth_hint_max_dt, 0.04);
  EXPECT_DOUBLE_EQ(c.keypoint_depth_max_dt, 0.07);
  EXPECT_EQ(c.keypoint_depth_source, KeypointDepthSource::kFeatures);
  EXPECT_DOUBLE_EQ(c.map_voxel, 0.3);
}

TEST(SystemConfig, EstimatorKeysAreReadAndChecked) {
  const SystemConfig c = load(
      "estimator:\n"
      "  window_s: 2.0\n"
      "  visual_pixel_sigma: 4\n"
      "  lidar_drift_m: 0.004\n"
      "  lidar_drift_deg: 0.02\n"
      "  visual_drift_m: 0.03\n"
      "  visual_drift_deg: 0.2\n"
      "  motion_accel: 3.0\n"
      "  motion_angular_accel_deg: 45.0\n"
      "  gate_accept_after: 5\n"
      "  huber_delta: 2.0\n"
      "  max_iterations: 5\n");
  EXPECT_DOUBLE_EQ(c.estimator.window_s, 2.0);
  EXPECT_DOUBLE_EQ(c.estimator.visual_pixel_sigma, 4.0);
  EXPECT_DOUBLE_EQ(c.estimator.lidar_drift_m, 0.004);
  EXPECT_DOUBLE_EQ(c.estimator.lidar_drift_deg, 0.02);
  EXPECT_DOUBLE_EQ(c.estimator.visual_drift_m, 0.03);
  EXPECT_DOUBLE_EQ(c.estimator.visual_drift_deg, 0.2);
  EXPECT_DOUBLE_EQ(c.estimator.motion_accel, 3.0);
  EXPECT_DOUBLE_EQ(c.estimator.motion_angular_accel_deg, 45.0);
  EXPECT_EQ(c.estimator.gate_accept_after, 5);
  EXPECT_DOUBLE_EQ(c.estimator.huber_delta, 2.0);
  EXPECT_EQ(c.estimator.max_iterations, 5);
  EXPECT_THROW(load("estimator:\n  visual_pixel_sigma: -1\n"), lvslam::Error);
  EXPECT_THROW(load("estimator:\n  lidar_drift_m: -0.001\n"), lvslam::Error);
  EXPECT_THROW(load("estimator:\n  visual_drift_deg: -0.1\n"), lvslam::Error);
  EXPECT_THROW(load("estimator:\n  motion_accel: 0\n"), lvslam::Error);
  EXPECT_THROW(load("estimator:\n  window_s: .nan\n"), lvslam::Error);
  EXPECT_DOUBLE_EQ(load("estimator:\n  lidar_drift_deg: 0\n").estimator.lidar_drift_deg, 0.0);  // off
  // The superseded output fusion and its keys are gone.
  EXPECT_THROW(load("output_fusion:\n  enabled: true\n"), lvslam::Error);
  EXPECT_THROW(load("detection:\n  max_disagreement_m: 0.02\n"), lvslam::Error);
  const std::string typo = errorMessageOf([] { load("estimator:\n  visual_pixel_sigmas: 3\n"); });
  EXPECT_NE(typo.find("visual_pixel_sigmas"), std::string::npos) << typo;
}

TEST(SystemConfig, EachAblationSwitchesOffItsContribution) {
  const auto ablated = [](const char* name) {
    SystemConfig c;
    applyAblation(c, name, "--ablate");
    return c;
  };
  EXPECT_FALSE(ablated("direction-residual").visual.modules.local_window.ba.use_direction_residual);
  EXPECT_FALSE(ablated("lidar-direction-refinement").lidar_direction_refinement);
  EXPECT_FALSE(ablated("fusion-lines").fusion_lines_in_tracking);
  EXPECT_FALSE(ablated("keypoint-depths").visual.modules.use_keypoint_depths);
  const SystemConfig paper_output = ablated("paper-output");
  EXPECT_TRUE(paper_output.paper_output);
  EXPECT_FALSE(SystemConfig{}.paper_output);
  EXPECT_TRUE(paper_output.fusion_lines_in_tracking);
  EXPECT_EQ(std::size(kAblations), 5u);
  const std::string message = errorMessageOf([] {
    SystemConfig c;
    applyAblation(c, "output", "--ablate");
  });
  EXPECT_NE(message.find("--ablate"), std::string::npos) << message;
  EXPECT_NE(message.find("paper-output"), std::string::npos) << message;
}

TEST(SystemConfig, AMisspeltSectionIsAnErrorNamingIt) {
  const std::string message = errorMessageOf([] { load("output_fuson:\n  enabled: false\n"); });
  EXPECT_EQ(message, "test.yaml: key 'output_fuson': unknown key (config/advanced.yaml lists every key)");
}

TEST(SystemConfig, KeypointDepthsComeFromScansUnlessToldOtherwise) {
  EXPECT_EQ(load("{}").keypoint_depth_source, KeypointDepthSource::kScans);
  const std::string message = errorMessageOf([] { load("system:\n  keypoint_depth_source: lidar\n"); });
  EXPECT_NE(message.find("keypoint_depth_source"), std::string::npos) << message;
  EXPECT_NE(message.find("must be one of 'scans', 'features', not 'lidar'"), std::string::npos) << message;
}

TEST(SystemConfig, TheShippedSimConfigLoads) {
  const std::string path = std::string(LVSLAM_SOURCE_DIR) + "/config/sim.yaml";
  EXPECT_NO_THROW(loadSystemConfig(YamlConfig::loadFile(path)));
}

TEST(SystemConfig, UnknownDetectionKeyNamesFileAndKey) {
  lvslam::testing::TempDir dir;
  dir.write("bad.yaml", "detection:\n  frames_to_recovr: 3\n");
  const std::string message = errorMessageOf([&] { loadSystemConfig(YamlConfig::loadFile(dir.file("bad.yaml"))); });
  EXPECT_NE(message.find(dir.file("bad.yaml")), std::string::npos) << message;
  EXPECT_NE(message.find("detection"), std::string::npos) << message;
  EXPECT_NE(message.find("frames_to_recovr"), std::string::npos) << message;
  EXPECT_THROW(loadSystemConfig(YamlConfig::loadFile(dir.file("bad.yaml"))), lvslam::Error);
}

TEST(SystemConfig, UnknownSystemKeyNamesFileAndKey) {
  const std::string message = errorMessageOf([] { load("system:\n  map_voxels: 0.3\n"); });
  EXPECT_NE(message.find("test.yaml"), std::string::npos) << message;
  EXPECT_NE(message.find("system"), std::string::npos) << message;
  EXPECT_NE(message.find("map_voxels"), std::string::npos) << message;
  EXPECT_THROW(load("system:\n  map_voxels: 0.3\n"), lvslam::Error);
}

TEST(SystemConfig, InvalidValuesAreErrorsNamingTheKey) {
  EXPECT_THROW(load("detection:\n  frames_to_recover: 0\n"), lvslam::Error);
  EXPECT_THROW(load("detection:\n  min_inlier_ratio: 1.5\n"), lvslam::Error);
  EXPECT_THROW(load("detection:\n  min_brightness: 200\n  max_brightness: 100\n"), lvslam::Error);
  EXPECT_THROW(load("detection:\n  max_disagreement_m: 0\n"), lvslam::Error);
  EXPECT_THROW(load("detection:\n  rejoin_step_m: -0.001\n"), lvslam::Error);
  EXPECT_THROW(load("detection:\n  min_tracked_points: -1\n"), lvslam::Error);
  const std::string voxel = errorMessageOf([] { load("system:\n  map_voxel: -0.2\n"); });
  EXPECT_NE(voxel.find("system.map_voxel"), std::string::npos) << voxel;
  const std::string dt = errorMessageOf([] { load("system:\n  depth_hint_max_dt: 0\n"); });
  EXPECT_NE(dt.find("system.depth_hint_max_dt"), std::string::npos) << dt;
  const std::string keyframe_dt = errorMessageOf([] { load("system:\n  keypoint_depth_max_dt: -0.1\n"); });
  EXPECT_NE(keyframe_dt.find("system.keypoint_depth_max_dt"), std::string::npos) << keyframe_dt;
  EXPECT_THROW(load("system:\n  map_voxel: .nan\n"), lvslam::Error);
  EXPECT_THROW(load("system:\n  final_map_poses: maybe\n"), lvslam::Error);
}

// Switching off one of the paper's contributions is --ablate's, not a file's.
TEST(SystemConfig, AblationSwitchesAreNotKeys) {
  for (const char* text : {"system:\n  fusion_lines_in_tracking: false\n", "system:\n  lidar_direction_refinement: false\n"}) {
    const std::string message = errorMessageOf([&] { load(text); });
    EXPECT_NE(message.find("unknown key"), std::string::npos) << message;
  }
}

TEST(SystemConfig, ErrorsOfTheSubsystemSectionsPropagate) {
  EXPECT_THROW(load("lidar:\n  preprocess:\n    voxel_sise: 0.3\n"), lvslam::Error);
  EXPECT_THROW(load("visual:\n  orb:\n    max_featurs: 10\n"), lvslam::Error);
  EXPECT_THROW(load("fusion:\n  arc_stepdeg: 0.2\n"), lvslam::Error);
}

TEST(RunMode, ParsesTheThreeNamesAndRoundTrips) {
  for (const RunMode mode : {RunMode::kLidar, RunMode::kVisual, RunMode::kFused})
    EXPECT_EQ(parseRunMode(runModeName(mode), "--mode"), mode);
  EXPECT_EQ(parseRunMode("lidar", "--mode"), RunMode::kLidar);
}

TEST(RunMode, UnknownNameIsAnErrorNamingWhere) {
  try {
    parseRunMode("Fused", "--mode");
    FAIL() << "no error";
  } catch (const lvslam::Error& e) {
    EXPECT_EQ(e.where(), "--mode");
    EXPECT_NE(e.why().find("Fused"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parseRunMode("", "--mode"), lvslam::Error);
}

}  // namespace
}  // namespace lvslam::system
