#pragma once
// Parameters of the fusion framework, with the defaults that
// config/advanced.yaml shows under its `fusion:` section.
#include <string>

#include "lvslam/core/config_keys.h"
#include "lvslam/core/yaml_config.h"

namespace lvslam::fusion {

struct FusionConfig {
  double arc_step_deg = 0.2;              // delta_phi: arc sampling step on the sphere
  // Chosen on simulated room and hall frames (docs/benchmarks.md, "Fusion
  // framework"): the LiDAR subsystem's features are voxel-thinned (0.3-0.5 m),
  // so even five accumulated scans leave a few degrees between neighbours on
  // the sphere.
  double max_neighbour_angle_deg = 3.0;   // a sample's neighbour must be this close on the sphere
  double min_matched_ratio = 0.5;         // share of arc samples that must find a neighbour
  int min_neighbours = 8;                 // distinct LiDAR points behind one line
  double majority_ratio = 0.6;            // share of one shape that decides the case
  double cluster_angle_deg = 10.0;        // directions within this angle form one cluster
  double max_relative_depth_error = 0.05; // neighbour distance to the line over its depth
  double min_depth_inlier_ratio = 0.7;    // share of neighbours that must agree in depth
  double max_case_disagreement_deg = 5.0; // planar and linear answers must agree this well
  double max_line_off_plane_deg = 5.0;    // linear case: line must lie in the image line's plane
  double min_plane_angle_deg = 20.0;      // planar case: LiDAR plane vs back-projected plane (grazing: depth unstable)
  double min_segment_length_px = 30.0;
  double min_depth = 0.3, max_depth = 60.0;
  int accumulated_scans = 5;              // the current and the last four scans
};

// The keys of the `fusion:` section, bound to `config`.
ConfigKeys configKeys(FusionConfig& config);
// Reads the `fusion` section of a YAML file (absent: defaults). Unknown or
// malformed keys throw lvslam::Error naming the file and the key.
FusionConfig loadFusionConfig(const YamlConfig& root);
// Throws lvslam::Error(file, "key 'fusion.<name>': ...") on values that cannot work.
void validate(const FusionConfig& config, const std::string& file);

}  // namespace lvslam::fusion
