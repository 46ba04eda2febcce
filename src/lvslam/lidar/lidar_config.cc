#include "lvslam/lidar/lidar_config.h"

#include <map>
#include <string>
#include <variant>

#include "lvslam/core/error.h"

namespace lvslam::lidar {

namespace {

using Field = std::variant<double*, int*, bool*, std::size_t*>;
using FieldTable = std::map<std::string, Field>;

// One table of key -> member keeps the YAML names and the struct in one place.
std::map<std::string, FieldTable> fieldTables(LidarOdometryConfig& c) {
  auto& p = c.preprocess;
  auto& g = c.ground;
  auto& f = c.features;
  auto& r = c.registration;
  auto& m = c.local_map;
  return {
      {"", {{"deskew", &c.deskew}, {"recent_frames", &c.recent_frames}, {"max_time_gap", &c.max_time_gap}}},
      {"preprocess", {{"min_range", &p.min_range}, {"max_range", &p.max_range}, {"voxel_size", &p.voxel_size},
        {"voxel_angle_deg", &p.voxel_angle_deg}}},
      {"ground",
       {{"grid_size", &g.grid_size}, {"height_threshold", &g.height_threshold},
        {"inlier_distance", &g.inlier_distance},
        {"max_normal_angle_deg", &g.max_normal_angle_deg}, {"min_points_per_cell", &g.min_points_per_cell},
        {"max_sensor_height", &g.max_sensor_height}}},
      {"features",
       {{"neighbours", &f.neighbours}, {"neighbour_radius", &f.neighbour_radius},
        {"min_neighbours", &f.min_neighbours}, {"candidate_voxel", &f.candidate_voxel},
        {"linearity_threshold", &f.linearity_threshold},
        {"planarity_threshold", &f.planarity_threshold}, {"curvature_threshold", &f.curvature_threshold},
        {"vertical_cos", &f.vertical_cos}, {"horizontal_cos", &f.horizontal_cos},
        {"ground_voxel", &f.ground_voxel}, {"planar_voxel", &f.planar_voxel},
        {"linear_voxel", &f.linear_voxel}, {"vertex_voxel", &f.vertex_voxel}}},
      {"registration",
       {{"max_iterations", &r.max_iterations}, {"converged_translation", &r.converged_translation},
        {"converged_rotation", &r.converged_rotation},
        {"reassociate_motion", &r.reassociate_motion}, {"initial_threshold", &r.initial_threshold},
        {"min_threshold", &r.min_threshold}, {"max_threshold", &r.max_threshold},
        {"degeneracy_ratio", &r.degeneracy_ratio}, {"min_correspondences", &r.min_correspondences},
        {"min_inlier_ratio", &r.min_inlier_ratio}, {"restart_after_lost", &r.restart_after_lost},
        {"max_correction_translation", &r.max_correction_translation},
        {"max_correction_rotation_deg", &r.max_correction_rotation_deg}, {"vertex_weight", &r.vertex_weight}, {"beam_weight", &r.beam_weight},
        {"max_normal_angle_deg", &r.max_normal_angle_deg}, {"range_sigma", &r.range_sigma},
        {"beam_divergence", &r.beam_divergence}}},
      {"local_map",
       {{"voxel_size", &m.voxel_size}, {"max_points_per_voxel", &m.max_points_per_voxel},
        {"radius", &m.radius}, {"max_frame_age", &m.max_frame_age},
        {"refined_rate_alpha", &m.refined_rate_alpha}}},
  };
}

void readField(const YamlConfig& node, const Field& field) {
  if (auto* d = std::get_if<double*>(&field)) **d = node.asDouble();
  if (auto* i = std::get_if<int*>(&field)) **i = node.asInt();
  if (auto* b = std::get_if<bool*>(&field)) **b = node.asBool();
  if (auto* s = std::get_if<std::size_t*>(&field)) {
    const int v = node.asInt();
    if (v < 0) node.fail("must not be negative");
    **s = static_cast<std::size_t>(v);
  }
}

void readTable(const YamlConfig& section, const std::map<std::string, FieldTable>& tables,
               const std::string& table_name) {
  if (!section.node().IsMap()) section.fail("expected a mapping");
  const FieldTable& table = tables.at(table_name);
  for (const auto& item : section.node()) {
    const std::string key = item.first.as<std::string>();
    const YamlConfig child = section.at(key);
    if (table_name.empty() && tables.count(key) && !key.empty()) {
      readTable(child, tables, key);
      continue;
    }
    const auto it = table.find(key);
    if (it == table.end()) child.fail("unknown key");
    readField(child, it->second);
  }
}

void require(bool ok, const std::string& where, const std::string& why) {
  if (!ok) throw Error(where, why);
}

}  // namespace

LidarOdometryConfig loadLidarOdometryConfig(const YamlConfig& root) {
  LidarOdometryConfig config;
  const auto section = root.find("lidar");
  if (!section) return config;
  readTable(*section, fieldTables(config), "");
  validate(config, section->file());
  return config;
}

void validate(const LidarOdometryConfig& c, const std::string& where) {
  const std::string k = "key 'lidar.";
  require(c.preprocess.min_range >= 0 && c.preprocess.max_range > c.preprocess.min_range, where,
          k + "preprocess': need 0 <= min_range < max_range");
  require(c.preprocess.voxel_size > 0, where, k + "preprocess.voxel_size': must be positive");
  require(c.preprocess.voxel_angle_deg >= 0 && c.preprocess.voxel_angle_deg < 45, where,
          k + "preprocess.voxel_angle_deg': must be in [0, 45)");
  require(c.ground.grid_size > 0 && c.ground.height_threshold > 0 && c.ground.inlier_distance > 0, where,
          k + "ground': grid_size, height_threshold and inlier_distance must be positive");
  require(c.features.neighbours >= 3 && c.features.min_neighbours >= 3 &&
              c.features.min_neighbours <= c.features.neighbours,
          where, k + "features': need 3 <= min_neighbours <= neighbours");
  require(c.features.ground_voxel > 0 && c.features.planar_voxel > 0 && c.features.linear_voxel > 0 &&
              c.features.vertex_voxel > 0 && c.features.neighbour_radius > 0,
          where, k + "features': voxel sizes and neighbour_radius must be positive");
  require(c.features.candidate_voxel >= 0, where, k + "features.candidate_voxel': must not be negative");
  require(c.registration.max_iterations > 0, where, k + "registration.max_iterations': must be positive");
  require(c.registration.reassociate_motion >= 0, where,
          k + "registration.reassociate_motion': must not be negative");
  require(c.registration.min_threshold > 0 && c.registration.min_threshold <= c.registration.max_threshold,
          where, k + "registration': need 0 < min_threshold <= max_threshold");
  require(c.registration.range_sigma > 0 && c.registration.beam_divergence >= 0, where,
          k + "registration': need range_sigma > 0 and beam_divergence >= 0");
  require(c.registration.restart_after_lost >= 0, where,
          k + "registration.restart_after_lost': must not be negative (0: never)");
  require(c.local_map.voxel_size > 0 && c.local_map.max_points_per_voxel > 0 && c.local_map.radius > 0 &&
              c.local_map.max_frame_age > 0,
          where, k + "local_map': sizes must be positive");
  require(c.local_map.refined_rate_alpha > 0 && c.local_map.refined_rate_alpha <= 1, where,
          k + "local_map.refined_rate_alpha': must be in (0, 1]");
  require(c.recent_frames >= 0 && c.max_time_gap > 0, where,
          k + "recent_frames' / 'max_time_gap': must be non-negative / positive");
}

}  // namespace lvslam::lidar
