#pragma once
// Every tunable of the visual subsystem in one plain struct, and its YAML
// section ("visual:" in config/*.yaml). Absent keys keep the defaults;
// unknown keys and invalid values are lvslam::Errors naming file and key.
#include "lvslam/core/yaml_config.h"
#include "lvslam/visual/feature/feature_extractor.h"
#include "lvslam/visual/initialize/two_view_initializer.h"
#include "lvslam/visual/match/line_matcher.h"
#include "lvslam/visual/match/point_matcher.h"
#include "lvslam/visual/optimize/local_window_adjustment.h"
#include "lvslam/visual/optimize/pose_optimization.h"
#include "lvslam/visual/tracking/local_keyframes.h"

namespace lvslam::visual {

struct VisualConfig {
  FeatureExtractorConfig features;
  PointMatcherConfig point_matching;
  LineMatcherConfig line_matching;
  PoseOptimizationConfig pose;
  LocalWindowConfig local_window;  // includes the BA settings
  TwoViewInitializerConfig initializer;
  LocalKeyframeConfig local_map;  // keyframes tracked against, nearby ones included (map reuse)
  // LiDAR depth of keyframe keypoints (VisualSlam::setKeypointDepths) enters
  // local BA as depth residuals (local_window.ba.depth_*); off: ignored.
  bool use_keypoint_depths = true;
  // The LiDAR odometry's pose of keyframes (VisualSlam::addLidarPose) enters
  // local BA as pose priors (local_window.ba.prior_*); off: ignored. Off by
  // default: measured mixed (room better, hall and gate worse,
  // docs/benchmarks.md "LiDAR pose priors"), so it is opt-in.
  bool use_lidar_pose_priors = false;
};

// `section` is the node of the "visual" key.
VisualConfig loadVisualConfig(const YamlConfig& section);

}  // namespace lvslam::visual
