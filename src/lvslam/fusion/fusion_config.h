#pragma once
// Parameters of the fusion framework, loaded from the `fusion:` section of a
// config file (fusion_config_yaml.h).
namespace lvslam::fusion {

struct FusionConfig {
  double arc_step_deg = 0.2;              // delta_phi: arc sampling step on the sphere
  double max_neighbour_angle_deg = 1.0;   // a sample's neighbour must be this close on the sphere
  double min_matched_ratio = 0.6;         // share of arc samples that must find a neighbour
  int min_neighbours = 6;                 // distinct LiDAR points behind one line
  double majority_ratio = 0.6;            // share of one shape that decides the case
  double cluster_angle_deg = 10.0;        // directions within this angle form one cluster
  double max_relative_depth_error = 0.05; // neighbour distance to the line over its depth
  double min_depth_inlier_ratio = 0.7;    // share of neighbours that must agree in depth
  double max_case_disagreement_deg = 5.0; // planar and linear answers must agree this well
  double max_line_off_plane_deg = 5.0;    // linear case: line must lie in the image line's plane
  double min_plane_angle_deg = 10.0;      // planar case: LiDAR plane vs back-projected plane
  double min_segment_length_px = 30.0;
  double min_depth = 0.3, max_depth = 60.0;
  int accumulated_scans = 5;              // the current and the last four scans
};

}  // namespace lvslam::fusion
