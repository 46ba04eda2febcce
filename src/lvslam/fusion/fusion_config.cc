#include "lvslam/fusion/fusion_config.h"

namespace lvslam::fusion {

ConfigKeys configKeys(FusionConfig& c) {
  ConfigKeys keys;
  keys.add("arc_step_deg", c.arc_step_deg)
      .add("max_neighbour_angle_deg", c.max_neighbour_angle_deg)
      .add("min_matched_ratio", c.min_matched_ratio)
      .add("min_neighbours", c.min_neighbours)
      .add("majority_ratio", c.majority_ratio)
      .add("cluster_angle_deg", c.cluster_angle_deg)
      .add("max_relative_depth_error", c.max_relative_depth_error)
      .add("min_depth_inlier_ratio", c.min_depth_inlier_ratio)
      .add("max_case_disagreement_deg", c.max_case_disagreement_deg)
      .add("max_line_off_plane_deg", c.max_line_off_plane_deg)
      .add("min_plane_angle_deg", c.min_plane_angle_deg)
      .add("min_segment_length_px", c.min_segment_length_px)
      .add("min_depth", c.min_depth)
      .add("max_depth", c.max_depth)
      .add("accumulated_scans", c.accumulated_scans);
  return keys;
}

FusionConfig loadFusionConfig(const YamlConfig& root) { return loadSection<FusionConfig>(root, "fusion"); }

namespace {

bool isRatio(double v) { return v > 0.0 && v <= 1.0; }
bool isAngle(double v, double max) { return v > 0.0 && v < max; }

}  // namespace

void validate(const FusionConfig& c, const std::string& file) {
  const ValueCheck check(file, "fusion");
  check(isAngle(c.arc_step_deg, 10.0), "arc_step_deg", "must be in (0, 10)");
  check(isAngle(c.max_neighbour_angle_deg, 10.0), "max_neighbour_angle_deg", "must be in (0, 10)");
  check(isRatio(c.min_matched_ratio), "min_matched_ratio", "must be in (0, 1]");
  check(c.min_neighbours >= 2, "min_neighbours", "must be at least 2");
  check(c.majority_ratio > 0.5 && c.majority_ratio <= 1.0, "majority_ratio", "must be in (0.5, 1]");
  check(isAngle(c.cluster_angle_deg, 90.0), "cluster_angle_deg", "must be in (0, 90)");
  check(isRatio(c.max_relative_depth_error), "max_relative_depth_error", "must be in (0, 1]");
  check(isRatio(c.min_depth_inlier_ratio), "min_depth_inlier_ratio", "must be in (0, 1]");
  check(isAngle(c.max_case_disagreement_deg, 90.0), "max_case_disagreement_deg", "must be in (0, 90)");
  check(isAngle(c.max_line_off_plane_deg, 90.0), "max_line_off_plane_deg", "must be in (0, 90)");
  check(isAngle(c.min_plane_angle_deg, 90.0), "min_plane_angle_deg", "must be in (0, 90)");
  check(c.min_segment_length_px >= 0.0, "min_segment_length_px", "must not be negative");
  check(c.min_depth >= 0.0 && c.max_depth > c.min_depth, "min_depth",
        "need 0 <= min_depth < max_depth");
  check(c.accumulated_scans >= 1, "accumulated_scans", "must be at least 1");
}

}  // namespace lvslam::fusion
