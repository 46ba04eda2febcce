#include "lvslam/fusion/fusion_config.h"

#include <map>
#include <variant>

#include "lvslam/core/error.h"

namespace lvslam::fusion {

namespace {

using Field = std::variant<double*, int*>;

// One table of key -> member keeps the YAML names and the struct in one place.
std::map<std::string, Field> fieldTable(FusionConfig& c) {
  return {{"arc_step_deg", &c.arc_step_deg},
          {"max_neighbour_angle_deg", &c.max_neighbour_angle_deg},
          {"min_matched_ratio", &c.min_matched_ratio},
          {"min_neighbours", &c.min_neighbours},
          {"majority_ratio", &c.majority_ratio},
          {"cluster_angle_deg", &c.cluster_angle_deg},
          {"max_relative_depth_error", &c.max_relative_depth_error},
          {"min_depth_inlier_ratio", &c.min_depth_inlier_ratio},
          {"max_case_disagreement_deg", &c.max_case_disagreement_deg},
          {"max_line_off_plane_deg", &c.max_line_off_plane_deg},
          {"min_plane_angle_deg", &c.min_plane_angle_deg},
          {"min_segment_length_px", &c.min_segment_length_px},
          {"min_depth", &c.min_depth},
          {"max_depth", &c.max_depth},
          {"accumulated_scans", &c.accumulated_scans}};
}

void require(bool ok, const std::string& where, const std::string& key, const std::string& why) {
  if (!ok) throw Error(where, "key 'fusion." + key + "': " + why);
}

bool isRatio(double v) { return v > 0.0 && v <= 1.0; }
bool isAngle(double v, double max) { return v > 0.0 && v < max; }

}  // namespace

FusionConfig loadFusionConfig(const YamlConfig& root) {
  FusionConfig config;
  const auto section = root.find("fusion");
  if (!section) return config;
  if (!section->node().IsMap()) section->fail("expected a mapping");
  const auto table = fieldTable(config);
  for (const auto& item : section->node()) {
    const std::string key = item.first.as<std::string>();
    const YamlConfig child = section->at(key);
    const auto it = table.find(key);
    if (it == table.end()) child.fail("unknown key");
    if (auto* d = std::get_if<double*>(&it->second)) **d = child.asDouble();
    if (auto* i = std::get_if<int*>(&it->second)) **i = child.asInt();
  }
  validate(config, section->file());
  return config;
}

void validate(const FusionConfig& c, const std::string& where) {
  require(isAngle(c.arc_step_deg, 10.0), where, "arc_step_deg", "must be in (0, 10)");
  require(isAngle(c.max_neighbour_angle_deg, 10.0), where, "max_neighbour_angle_deg", "must be in (0, 10)");
  require(isRatio(c.min_matched_ratio), where, "min_matched_ratio", "must be in (0, 1]");
  require(c.min_neighbours >= 2, where, "min_neighbours", "must be at least 2");
  require(c.majority_ratio > 0.5 && c.majority_ratio <= 1.0, where, "majority_ratio", "must be in (0.5, 1]");
  require(isAngle(c.cluster_angle_deg, 90.0), where, "cluster_angle_deg", "must be in (0, 90)");
  require(isRatio(c.max_relative_depth_error), where, "max_relative_depth_error", "must be in (0, 1]");
  require(isRatio(c.min_depth_inlier_ratio), where, "min_depth_inlier_ratio", "must be in (0, 1]");
  require(isAngle(c.max_case_disagreement_deg, 90.0), where, "max_case_disagreement_deg", "must be in (0, 90)");
  require(isAngle(c.max_line_off_plane_deg, 90.0), where, "max_line_off_plane_deg", "must be in (0, 90)");
  require(isAngle(c.min_plane_angle_deg, 90.0), where, "min_plane_angle_deg", "must be in (0, 90)");
  require(c.min_segment_length_px >= 0.0, where, "min_segment_length_px", "must not be negative");
  require(c.min_depth >= 0.0 && c.max_depth > c.min_depth, where, "min_depth",
          "need 0 <= min_depth < max_depth");
  require(c.accumulated_scans >= 1, where, "accumulated_scans", "must be at least 1");
}

}  // namespace lvslam::fusion
