#include "lvslam/visual/visual_config.h"

#include <string>
#include <utility>

#include "lvslam/core/error.h"
#include "lvslam/visual/tracking/visual_slam_config.h"

namespace lvslam::visual {

namespace {

void addFeatureKeys(ConfigKeys& keys, FeatureExtractorConfig& f) {
  auto& orb = f.orb;
  auto& lines = f.lines;
  keys.add("orb.max_features", orb.max_features)
      .add("orb.scale_factor", orb.scale_factor)
      .add("orb.num_levels", orb.num_levels)
      .add("orb.fast_threshold", orb.fast_threshold)
      .add("orb.candidate_factor", orb.candidate_factor)
      .add("orb.grid_cell_size", orb.grid_cell_size)
      .add("orb.edge_threshold", orb.edge_threshold);
  keys.add("lines.enabled", f.extract_lines)
      .add("lines.scale", lines.scale)
      .add("lines.sigma_scale", lines.sigma_scale)
      .add("lines.quant", lines.quant)
      .add("lines.angle_threshold_deg", lines.angle_threshold_deg)
      .add("lines.density_threshold", lines.density_threshold)
      .add("lines.n_bins", lines.n_bins)
      .add("lines.min_length_ratio", lines.min_length_ratio)
      .add("lines.max_lines", lines.max_lines)
      .add("lines.descriptor_octave", lines.descriptor_octave);
}

// Start of a map and tracking of the frames after it.
void addTrackingKeys(ConfigKeys& keys, VisualSlamConfig& c) {
  auto& v = c.modules;
  keys.add("usability.min_keypoints", c.min_keypoints)
      .add("usability.min_brightness", c.usability.min_brightness)
      .add("usability.max_brightness", c.usability.max_brightness)
      .add("usability.min_contrast", c.usability.min_contrast);
  keys.add("initializer.window_px", c.init_window_px)
      .add("initializer.min_matches", c.min_init_matches)
      .add("initializer.max_frames", c.max_init_frames)
      .add("initializer.max_unhinted_references", c.max_unhinted_references)
      .add("initializer.min_depth_share", c.min_depth_share)
      .add("initializer.sigma_px", v.initializer.sigma_px)
      .add("initializer.homography_ratio", v.initializer.homography_ratio)
      .add("initializer.min_parallax_deg", v.initializer.min_parallax_deg)
      .add("initializer.min_triangulated", v.initializer.min_triangulated)
      .add("initializer.ambiguity_ratio_essential", v.initializer.ambiguity_ratio_essential)
      .add("initializer.ambiguity_ratio_homography", v.initializer.ambiguity_ratio_homography)
      .add("initializer.min_depth_hints", v.initializer.min_depth_hints);
  keys.add("point_matching.max_distance", v.point_matching.max_distance)
      .add("point_matching.ratio", v.point_matching.ratio)
      .add("point_matching.check_orientation", v.point_matching.check_orientation);
  keys.add("line_matching.max_distance", v.line_matching.max_distance)
      .add("line_matching.ratio", v.line_matching.ratio)
      .add("line_matching.max_angle_deg", v.line_matching.max_angle_deg)
      .add("line_matching.max_offset_px", v.line_matching.max_offset_px)
      .add("line_matching.max_line_distance_px", v.line_matching.max_line_distance_px);
  keys.add("tracking.search_radius_px", c.search_radius_px)
      .add("tracking.refine_radius_px", c.refine_radius_px)
      .add("tracking.max_descriptor_distance", c.track_max_distance)
      .add("tracking.recovery_radius_scale", c.recovery_radius_scale)
      .add("tracking.min_tracked", c.min_tracked)
      .add("tracking.fusion_line_lifetime", c.fusion_line_lifetime)
      .add("tracking.lidar_pose_buffer", c.lidar_pose_buffer);
  keys.add("relocalization.frames", c.relocalize_frames)
      .add("relocalization.candidates", c.relocalize_candidates)
      .add("relocalization.min_inliers", c.relocalize_min_inliers);
  keys.add("pose.rounds", v.pose.rounds)
      .add("pose.iterations_per_round", v.pose.iterations_per_round)
      .add("pose.chi2_point", v.pose.chi2_point)
      .add("pose.chi2_line", v.pose.chi2_line)
      .add("pose.huber_delta", v.pose.huber_delta)
      .add("pose.min_inliers", v.pose.min_inliers);
  keys.add("keyframes.tracked_ratio", v.keyframes.tracked_ratio)
      .add("keyframes.min_tracked", v.keyframes.min_tracked)
      .add("keyframes.min_interval", v.keyframes.min_interval)
      .add("keyframes.max_interval", v.keyframes.max_interval)
      .add("keyframes.min_inliers", v.keyframes.min_inliers);
  keys.add("local_keyframes.max_voted", v.local_map.max_voted)
      .add("local_keyframes.expanded", v.local_map.expanded)
      .add("local_keyframes.neighbours_each", v.local_map.neighbours_each);
  keys.add("map_reuse.radius_depths", v.local_map.nearby_radius_depths)
      .add("map_reuse.max_angle_deg", v.local_map.nearby_max_angle_deg)
      .add("map_reuse.max_keyframes", v.local_map.nearby_max)
      .add("map_reuse.min_age_keyframes", v.local_map.nearby_min_age);
}

// The local mapper: new landmarks, culling, bundle adjustment and what
// the LiDAR gives it.
void addMappingKeys(ConfigKeys& keys, VisualSlamConfig& c) {
  auto& t = c.triangulation;
  keys.add("triangulation.search_window_px", t.search_window_px)
      .add("triangulation.chi2_epipolar", t.chi2_epipolar)
      .add("triangulation.max_distance", t.max_distance)
      .add("triangulation.ratio", t.ratio)
      .add("triangulation.min_parallax_cos", t.min_parallax_cos)
      .add("triangulation.chi2_reprojection", t.chi2_reprojection)
      .add("triangulation.min_baseline_ratio", t.min_baseline_ratio)
      .add("triangulation.max_depth_points", t.max_depth_points);
  keys.add("culling.min_found_ratio", c.culling.min_found_ratio)
      .add("culling.probation_keyframes", c.culling.probation_keyframes)
      .add("culling.min_observations", c.culling.min_observations)
      .add("culling.release_keyframes", c.culling.release_keyframes)
      .add("culling.redundant_ratio", c.culling.redundant_ratio)
      .add("culling.redundant_observers", c.culling.redundant_observers);
  keys.add("line_depth_check.ratio", c.depth_check.ratio)
      .add("line_depth_check.fusion_ratio", c.depth_check.fusion_ratio);
  auto& w = c.modules.local_window;
  keys.add("bundle_adjustment.window_size", w.window_size)
      .add("bundle_adjustment.fixed_oldest", w.fixed_oldest)
      .add("bundle_adjustment.first_stage_iterations", w.ba.first_stage_iterations)
      .add("bundle_adjustment.second_stage_iterations", w.ba.second_stage_iterations)
      .add("bundle_adjustment.chi2_point", w.ba.chi2_point)
      .add("bundle_adjustment.chi2_line", w.ba.chi2_line)
      .add("bundle_adjustment.huber_delta", w.ba.huber_delta)
      .add("bundle_adjustment.direction_weight", w.ba.direction_weight)
      .add("bundle_adjustment.direction_huber_delta", w.ba.direction_huber_delta);
  keys.add("keypoint_depths.sigma_ratio", w.ba.depth_sigma_ratio)
      .add("keypoint_depths.huber_delta", w.ba.depth_huber_delta)
      .add("keypoint_depths.chi2", w.ba.chi2_depth);
  // The map correction's pose graph weighs its priors as local BA does.
  auto& m = c.modules.map_correction;
  keys.add("lidar_pose_priors.enabled", c.modules.use_lidar_pose_priors)
      .add("lidar_pose_priors.sigma_m", w.ba.prior_sigma_m, m.graph.prior_sigma_m)
      .add("lidar_pose_priors.sigma_deg", w.ba.prior_sigma_deg, m.graph.prior_sigma_deg)
      .add("lidar_pose_priors.huber_delta", w.ba.prior_huber_delta, m.graph.prior_huber_delta)
      .add("lidar_pose_priors.map_correction.every_keyframes", m.every_keyframes)
      .add("lidar_pose_priors.map_correction.window_keyframes", m.window_keyframes)
      .add("lidar_pose_priors.map_correction.min_covisibility", m.min_covisibility)
      .add("lidar_pose_priors.map_correction.sigma_m", m.graph.edge_sigma_m)
      .add("lidar_pose_priors.map_correction.sigma_deg", m.graph.edge_sigma_deg)
      .add("lidar_pose_priors.map_correction.iterations", m.graph.max_iterations);
}

void validateTracking(const VisualSlamConfig& c, const ValueCheck& check) {
  const VisualConfig& v = c.modules;
  check(c.min_keypoints >= 0, "usability.min_keypoints", "must not be negative");
  check(c.usability.min_brightness < c.usability.max_brightness, "usability.min_brightness",
        "need min_brightness < max_brightness");
  check(c.init_window_px > 0.0, "initializer.window_px", "must be positive");
  check(c.min_init_matches >= 8, "initializer.min_matches", "must be at least 8");
  check(c.max_init_frames >= 1, "initializer.max_frames", "must be at least 1");
  check(c.max_unhinted_references >= 0, "initializer.max_unhinted_references", "must not be negative");
  check(c.min_depth_share >= 0.0 && c.min_depth_share <= 1.0, "initializer.min_depth_share", "must be in [0, 1]");
  check(v.point_matching.ratio > 0.0 && v.point_matching.ratio <= 1.0, "point_matching.ratio", "must be in (0, 1]");
  check(v.line_matching.ratio > 0.0 && v.line_matching.ratio <= 1.0, "line_matching.ratio", "must be in (0, 1]");
  check(c.search_radius_px > 0.0, "tracking.search_radius_px", "must be positive");
  check(c.refine_radius_px > 0.0, "tracking.refine_radius_px", "must be positive");
  check(c.track_max_distance >= 0 && c.track_max_distance <= 256, "tracking.max_descriptor_distance", "must be in [0, 256]");
  check(c.recovery_radius_scale >= 1.0, "tracking.recovery_radius_scale", "must be at least 1");
  check(c.min_tracked >= 0, "tracking.min_tracked", "must not be negative");
  check(c.fusion_line_lifetime >= 0, "tracking.fusion_line_lifetime", "must not be negative");
  check(c.relocalize_frames >= 0, "relocalization.frames", "must not be negative");
  check(v.pose.rounds >= 1, "pose.rounds", "must be at least 1");
  check(v.pose.iterations_per_round >= 1, "pose.iterations_per_round", "must be at least 1");
  const KeyframePolicy& k = v.keyframes;
  check(k.tracked_ratio > 0.0 && k.tracked_ratio <= 1.0, "keyframes.tracked_ratio", "must be in (0, 1]");
  check(k.min_tracked >= 0, "keyframes.min_tracked", "must be >= 0");
  check(k.min_inliers >= 0, "keyframes.min_inliers", "must be >= 0");
  check(k.min_interval >= 1 && k.max_interval >= k.min_interval, "keyframes.min_interval",
        "1 <= min_interval <= max_interval required, got " + std::to_string(k.min_interval) + " and " +
            std::to_string(k.max_interval));
  const LocalKeyframeConfig& m = v.local_map;
  check(m.nearby_radius_depths >= 0.0, "map_reuse.radius_depths", "must not be negative (0: off)");
  check(m.nearby_max_angle_deg > 0.0 && m.nearby_max_angle_deg <= 180.0, "map_reuse.max_angle_deg",
        "must be in (0, 180]");
}

void validateMapping(const VisualSlamConfig& c, const ValueCheck& check) {
  const LocalWindowConfig& w = c.modules.local_window;
  check(c.triangulation.ratio > 0.0 && c.triangulation.ratio <= 1.0, "triangulation.ratio", "must be in (0, 1]");
  check(c.triangulation.max_depth_points >= 0, "triangulation.max_depth_points", "must not be negative");
  check(c.culling.min_found_ratio >= 0.0 && c.culling.min_found_ratio <= 1.0, "culling.min_found_ratio",
        "must be in [0, 1]");
  check(c.culling.redundant_ratio > 0.0 && c.culling.redundant_ratio <= 1.0, "culling.redundant_ratio",
        "must be in (0, 1]");
  check(c.depth_check.ratio > 0.0, "line_depth_check.ratio", "must be positive");
  check(c.depth_check.fusion_ratio > 0.0, "line_depth_check.fusion_ratio", "must be positive");
  check(w.window_size >= 2, "bundle_adjustment.window_size", "must be at least 2");
  check(w.fixed_oldest >= 1, "bundle_adjustment.fixed_oldest", "must be at least 1");
  check(w.ba.first_stage_iterations >= 1, "bundle_adjustment.first_stage_iterations", "must be at least 1");
  check(w.ba.second_stage_iterations >= 0, "bundle_adjustment.second_stage_iterations", "must not be negative");
  check(w.ba.direction_weight >= 0.0, "bundle_adjustment.direction_weight", "must not be negative");
  check(w.ba.direction_huber_delta > 0.0, "bundle_adjustment.direction_huber_delta", "must be positive");
  check(w.ba.depth_sigma_ratio > 0.0, "keypoint_depths.sigma_ratio", "must be positive");
  check(w.ba.depth_huber_delta > 0.0, "keypoint_depths.huber_delta", "must be positive");
  check(w.ba.prior_sigma_m > 0.0, "lidar_pose_priors.sigma_m", "must be positive");
  check(w.ba.prior_sigma_deg > 0.0, "lidar_pose_priors.sigma_deg", "must be positive");
  check(w.ba.prior_huber_delta > 0.0, "lidar_pose_priors.huber_delta", "must be positive");
  const MapCorrectionConfig& m = c.modules.map_correction;
  const std::string correction = "lidar_pose_priors.map_correction.";
  check(m.every_keyframes >= 0, correction + "every_keyframes", "must not be negative (0: never)");
  check(m.window_keyframes >= 0, correction + "window_keyframes", "must not be negative (0: the whole map)");
  check(m.min_covisibility >= 1, correction + "min_covisibility", "must be at least 1");
  check(m.graph.edge_sigma_m > 0.0, correction + "sigma_m", "must be positive");
  check(m.graph.edge_sigma_deg > 0.0, correction + "sigma_deg", "must be positive");
  check(m.graph.max_iterations >= 1, correction + "iterations", "must be at least 1");
}

}  // namespace

ConfigKeys configKeys(VisualSlamConfig& config) {
  ConfigKeys keys;
  addFeatureKeys(keys, config.modules.features);
  addTrackingKeys(keys, config);
  addMappingKeys(keys, config);
  return keys;
}

void validate(const VisualSlamConfig& config, const std::string& file) {
  const ValueCheck check(file, "visual");
  validateTracking(config, check);
  validateMapping(config, check);
  // The extractors and the initializer check the rest of their settings
  // when constructed; do it now so that a bad file fails at load time.
  const auto constructs = [&](const std::string& key, const auto& construct) {
    try {
      construct();
    } catch (const Error& e) {
      check(false, key, e.why());
    }
  };
  constructs("orb", [&] { OrbExtractor orb(config.modules.features.orb); });
  constructs("lines", [&] { LineExtractor lines(config.modules.features.lines); });
  constructs("initializer", [&] { TwoViewInitializer init(config.modules.initializer, PinholeIntrinsics{}); });
}

}  // namespace lvslam::visual
