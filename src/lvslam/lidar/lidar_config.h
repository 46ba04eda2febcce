#pragma once
// Every tunable of the LiDAR subsystem (MULLS-style odometry), with the
// defaults that config/advanced.yaml shows under its `lidar:` section.
#include <cstddef>
#include <string>

#include "lvslam/core/config_keys.h"
#include "lvslam/core/yaml_config.h"

namespace lvslam::lidar {

struct PreprocessConfig {
  double min_range = 0.8;    // metres; closer returns hit the robot itself
  double max_range = 60.0;   // metres
  double voxel_size = 0.25;  // metres, downsampling before PCA
  // Far away the voxel grows to span this angle (0: one size everywhere).
  double voxel_angle_deg = 1.0;
};

struct GroundConfig {
  double grid_size = 2.0;          // metres, cells of the ground grid
  double height_threshold = 0.15;  // metres above a cell's lowest point: candidates
  double inlier_distance = 0.05;   // metres from the cell's fitted plane: ground
  double max_normal_angle_deg = 15.0;
  int min_points_per_cell = 4;
  double max_sensor_height = -0.3;  // ground lies below z = this in the LiDAR frame
};

struct FeatureConfig {
  int neighbours = 30;            // k of the PCA neighbourhood
  double neighbour_radius = 1.0;  // metres; farther neighbours are ignored
  int min_neighbours = 6;
  // Non-ground points are thinned to one per voxel of this size (metres)
  // before PCA; 0 classifies every point.
  // 0 by default: the fusion framework needs the dense classified cloud (the
  // paper's "dense geometric point cloud"); 0.3 is the fast LiDAR-only choice.
  double candidate_voxel = 0.0;
  double linearity_threshold = 0.65;   // (l1 - l2) / l1
  double planarity_threshold = 0.65;   // (l2 - l3) / l1
  double curvature_threshold = 0.12;   // l3 / (l1 + l2 + l3)
  double vertical_cos = 0.8;     // |dir . z| above: vertical
  double horizontal_cos = 0.3;   // |dir . z| below: horizontal
  // Per-class downsampling of the registration source (MULLS keeps few ground points).
  double ground_voxel = 1.0;
  double planar_voxel = 0.5;
  double linear_voxel = 0.3;
  double vertex_voxel = 0.6;
};

struct RegistrationConfig {
  int max_iterations = 12;
  double converged_translation = 1e-4;  // metres
  double converged_rotation = 1e-4;     // radians
  // Nearest neighbours are searched again only once the pose moved this far
  // (metres at 10 m) since the last search; 0 searches every iteration.
  double reassociate_motion = 0.02;
  double initial_threshold = 1.0;  // metres, correspondence distance before the adaptive threshold knows better
  double min_threshold = 0.15;     // metres
  double max_threshold = 2.0;      // metres
  // A residual row counts toward a principal direction's localizability
  // only within this angle of it (X-ICP); a direction is localizable when
  // those rows fix it to within the robust kernel (a third of the threshold).
  double localizability_angle_deg = 75.0;
  std::size_t min_correspondences = 30;
  // Correspondences per feature, relative to the mean of the last good
  // registrations (1 before any); fewer: registered to the wrong place.
  // Relative, because a young map matches less of a rightly registered scan
  // than a grown one; 0.5 lies between what right registrations of the
  // simulated scenes keep and what a slip along the repetitive synthetic hall
  // of tests/lidar keeps (docs/history/2026-11-21-components.md, "Speed";
  // docs/history/2026-11-fusion-sessions.md, "Fused mode over nine sequences").
  double min_inlier_ratio = 0.5;
  // Registrations lost in a row (with enough features) after which the local
  // map restarts from the scan at its predicted pose, so that a map the
  // scans no longer match cannot leave the odometry lost for good. 0: never.
  int restart_after_lost = 3;
  double max_correction_translation = 2.0;  // metres away from the prediction: lost
  double max_correction_rotation_deg = 30.0;
  double vertex_weight = 0.5;  // point-to-point residuals are the least informative
  // Horizontal "lines" of a sparse scan are often strips of a wall at the edge
  // of the view (their eigenvalues say linear); they get a small say.
  double beam_weight = 0.0;
  double max_normal_angle_deg = 30.0;  // source and map directions must agree this well
  // The sensor's own noise, which weighs each correspondence: a return's
  // position is uncertain by its range noise and by where in the beam's
  // footprint (full angle beam_divergence) the echo came from.
  double range_sigma = 0.02;         // metres (VLP-32C: +-3 cm accuracy)
  double beam_divergence = 0.003;    // radians, full angle (VLP-32C and VLP-16: 3 mrad)
};

struct LocalMapConfig {
  double voxel_size = 0.5;          // metres
  int max_points_per_voxel = 12;    // per voxel, all classes together
  double radius = 60.0;             // metres around the sensor
  int max_frame_age = 150;          // frames; older map points are dropped
  double refined_rate_alpha = 0.3;  // paper: largest rate of direction-refined points in the map
};

struct LidarOdometryConfig {
  PreprocessConfig preprocess;
  GroundConfig ground;
  FeatureConfig features;
  RegistrationConfig registration;
  LocalMapConfig local_map;
  bool deskew = true;
  int recent_frames = 4;       // frames whose features the fusion framework sees
  double max_time_gap = 0.5;   // seconds between scans; longer: motion unknown
  // The velocity that predicts and deskews the next scan changes by about
  // this much per second (1 sigma): a registration's step along a direction
  // it saw poorly moves it only as far as the two uncertainties say.
  double motion_accel = 2.0;              // m/s^2
  double motion_angular_accel_deg = 90.0;  // deg/s^2
};

// The keys of the `lidar:` section ("preprocess.min_range"), bound to `config`.
ConfigKeys configKeys(LidarOdometryConfig& config);
// Reads the `lidar` section of a YAML file (absent: defaults). Unknown or
// malformed keys throw lvslam::Error naming the file and the key.
LidarOdometryConfig loadLidarOdometryConfig(const YamlConfig& root);
// Throws lvslam::Error(file, "key 'lidar.<key>': ...") on values that cannot work.
void validate(const LidarOdometryConfig& config, const std::string& file);

}  // namespace lvslam::lidar
