#pragma once
// The visual subsystem's algorithm settings in one plain struct, and the
// keys of the `visual:` section of the configuration (config/advanced.yaml),
// which also reach VisualSlamConfig's own (tracking/visual_slam_config.h).
#include <string>

#include "lvslam/core/config_keys.h"
#include "lvslam/visual/feature/feature_extractor.h"
#include "lvslam/visual/initialize/two_view_initializer.h"
#include "lvslam/visual/match/line_matcher.h"
#include "lvslam/visual/match/point_matcher.h"
#include "lvslam/visual/module/odometry_map_correction.h"
#include "lvslam/visual/optimize/local_window_adjustment.h"
#include "lvslam/visual/optimize/pose_optimization.h"
#include "lvslam/visual/tracking/keyframe_policy.h"
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
  KeyframePolicy keyframes;       // when a tracked frame becomes a keyframe
  // LiDAR depth of keyframe keypoints (VisualSlam::setKeypointDepths) enters
  // local BA as depth residuals (local_window.ba.depth_*); off (--ablate
  // keypoint-depths): ignored.
  bool use_keypoint_depths = true;
  // The LiDAR odometry's pose of keyframes (VisualSlam::addLidarPose) enters
  // local BA as pose priors (local_window.ba.prior_*) and anchors the map
  // correction below; off: ignored. Only fused mode gives such poses. On: with
  // the map correction they lower the fused error
  // (docs/history/2026-11-fusion-sessions.md, "LiDAR-anchored map").
  bool use_lidar_pose_priors = true;
  // With the priors: the whole map is pulled onto the LiDAR poses every few
  // keyframes (pose graph; its prior sigmas are local BA's).
  MapCorrectionConfig map_correction;
};

struct VisualSlamConfig;
// The keys of the `visual:` section ("orb.max_features"), bound to `config`.
ConfigKeys configKeys(VisualSlamConfig& config);
// Throws lvslam::Error(file, "key 'visual.<key>': ...") on values that cannot work.
void validate(const VisualSlamConfig& config, const std::string& file);

}  // namespace lvslam::visual
