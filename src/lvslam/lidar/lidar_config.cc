#include "lvslam/lidar/lidar_config.h"

#include <string>
#include <utility>

namespace lvslam::lidar {

ConfigKeys configKeys(LidarOdometryConfig& c) {
  auto& p = c.preprocess;
  auto& g = c.ground;
  auto& f = c.features;
  auto& r = c.registration;
  auto& m = c.local_map;
  ConfigKeys keys;
  keys.add("deskew", c.deskew).add("recent_frames", c.recent_frames).add("max_time_gap", c.max_time_gap);
  keys.add("motion_accel", c.motion_accel).add("motion_angular_accel_deg", c.motion_angular_accel_deg);
  keys.add("preprocess.min_range", p.min_range)
      .add("preprocess.max_range", p.max_range)
      .add("preprocess.voxel_size", p.voxel_size)
      .add("preprocess.voxel_angle_deg", p.voxel_angle_deg);
  keys.add("ground.grid_size", g.grid_size)
      .add("ground.height_threshold", g.height_threshold)
      .add("ground.inlier_distance", g.inlier_distance)
      .add("ground.max_normal_angle_deg", g.max_normal_angle_deg)
      .add("ground.min_points_per_cell", g.min_points_per_cell)
      .add("ground.max_sensor_height", g.max_sensor_height);
  keys.add("features.neighbours", f.neighbours)
      .add("features.neighbour_radius", f.neighbour_radius)
      .add("features.min_neighbours", f.min_neighbours)
      .add("features.candidate_voxel", f.candidate_voxel)
      .add("features.linearity_threshold", f.linearity_threshold)
      .add("features.planarity_threshold", f.planarity_threshold)
      .add("features.curvature_threshold", f.curvature_threshold)
      .add("features.vertical_cos", f.vertical_cos)
      .add("features.horizontal_cos", f.horizontal_cos)
      .add("features.ground_voxel", f.ground_voxel)
      .add("features.planar_voxel", f.planar_voxel)
      .add("features.linear_voxel", f.linear_voxel)
      .add("features.vertex_voxel", f.vertex_voxel);
  keys.add("registration.max_iterations", r.max_iterations)
      .add("registration.converged_translation", r.converged_translation)
      .add("registration.converged_rotation", r.converged_rotation)
      .add("registration.reassociate_motion", r.reassociate_motion)
      .add("registration.initial_threshold", r.initial_threshold)
      .add("registration.min_threshold", r.min_threshold)
      .add("registration.max_threshold", r.max_threshold)
      .add("registration.localizability_angle_deg", r.localizability_angle_deg)
      .add("registration.min_correspondences", r.min_correspondences)
      .add("registration.min_inlier_ratio", r.min_inlier_ratio)
      .add("registration.restart_after_lost", r.restart_after_lost)
      .add("registration.max_correction_translation", r.max_correction_translation)
      .add("registration.max_correction_rotation_deg", r.max_correction_rotation_deg)
      .add("registration.vertex_weight", r.vertex_weight)
      .add("registration.beam_weight", r.beam_weight)
      .add("registration.max_normal_angle_deg", r.max_normal_angle_deg)
      .add("registration.range_sigma", r.range_sigma)
      .add("registration.beam_divergence", r.beam_divergence);
  keys.add("local_map.voxel_size", m.voxel_size)
      .add("local_map.max_points_per_voxel", m.max_points_per_voxel)
      .add("local_map.radius", m.radius)
      .add("local_map.max_frame_age", m.max_frame_age)
      .add("local_map.refined_rate_alpha", m.refined_rate_alpha);
  return keys;
}

LidarOdometryConfig loadLidarOdometryConfig(const YamlConfig& root) {
  return loadSection<LidarOdometryConfig>(root, "lidar");
}

void validate(const LidarOdometryConfig& c, const std::string& file) {
  const ValueCheck check(file, "lidar");
  const auto& p = c.preprocess;
  const auto& f = c.features;
  const auto& r = c.registration;
  const auto& m = c.local_map;
  check(p.min_range >= 0 && p.max_range > p.min_range, "preprocess.min_range", "need 0 <= min_range < max_range");
  check(p.voxel_size > 0, "preprocess.voxel_size", "must be positive");
  check(p.voxel_angle_deg >= 0 && p.voxel_angle_deg < 45, "preprocess.voxel_angle_deg", "must be in [0, 45)");
  check(c.ground.grid_size > 0, "ground.grid_size", "must be positive");
  check(c.ground.height_threshold > 0, "ground.height_threshold", "must be positive");
  check(c.ground.inlier_distance > 0, "ground.inlier_distance", "must be positive");
  check(f.neighbours >= 3 && f.min_neighbours >= 3 && f.min_neighbours <= f.neighbours, "features.min_neighbours",
        "need 3 <= min_neighbours <= neighbours");
  check(f.neighbour_radius > 0, "features.neighbour_radius", "must be positive");
  for (const auto& [key, voxel] : {std::pair{"ground_voxel", f.ground_voxel}, std::pair{"planar_voxel", f.planar_voxel},
                                   std::pair{"linear_voxel", f.linear_voxel}, std::pair{"vertex_voxel", f.vertex_voxel}})
    check(voxel > 0, std::string("features.") + key, "must be positive");
  check(f.candidate_voxel >= 0, "features.candidate_voxel", "must not be negative");
  check(r.max_iterations > 0, "registration.max_iterations", "must be positive");
  check(r.reassociate_motion >= 0, "registration.reassociate_motion", "must not be negative");
  check(r.min_threshold > 0 && r.min_threshold <= r.max_threshold, "registration.min_threshold",
        "need 0 < min_threshold <= max_threshold");
  check(r.localizability_angle_deg > 0 && r.localizability_angle_deg <= 90, "registration.localizability_angle_deg",
        "must be in (0, 90]");
  check(r.range_sigma > 0, "registration.range_sigma", "must be positive");
  check(r.beam_divergence >= 0, "registration.beam_divergence", "must not be negative");
  check(r.restart_after_lost >= 0, "registration.restart_after_lost", "must not be negative (0: never)");
  check(m.voxel_size > 0, "local_map.voxel_size", "must be positive");
  check(m.max_points_per_voxel > 0, "local_map.max_points_per_voxel", "must be positive");
  check(m.radius > 0, "local_map.radius", "must be positive");
  check(m.max_frame_age > 0, "local_map.max_frame_age", "must be positive");
  check(m.refined_rate_alpha > 0 && m.refined_rate_alpha <= 1, "local_map.refined_rate_alpha", "must be in (0, 1]");
  check(c.recent_frames >= 0, "recent_frames", "must not be negative");
  check(c.max_time_gap > 0, "max_time_gap", "must be positive");
  check(c.motion_accel > 0, "motion_accel", "must be positive");
  check(c.motion_angular_accel_deg > 0, "motion_angular_accel_deg", "must be positive");
}

}  // namespace lvslam::lidar
