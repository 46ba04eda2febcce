#include "lvslam/loop/loop_config.h"

#include <utility>

namespace lvslam::loop {

ConfigKeys configKeys(LoopClosureConfig& c) {
  ConfigKeys keys;
  keys.add("enabled", c.enabled)
      .add("keyframe_distance", c.keyframe_distance)
      .add("keyframe_angle_deg", c.keyframe_angle_deg)
      .add("scan_context.rings", c.scan_context.rings)
      .add("scan_context.sectors", c.scan_context.sectors)
      .add("scan_context.max_radius", c.scan_context.max_radius)
      .add("scan_context.height_offset", c.scan_context.height_offset)
      .add("exclude_recent_path", c.exclude_recent_path)
      .add("ring_key_candidates", c.ring_key_candidates)
      .add("max_descriptor_distance", c.max_descriptor_distance)
      .add("submap_keyframes", c.submap_keyframes)
      .add("max_rms", c.max_rms)
      .add("min_inlier_ratio", c.min_inlier_ratio)
      .add("odometry_sigma_m", c.odometry_sigma_m)
      .add("odometry_sigma_deg", c.odometry_sigma_deg)
      .add("odometry_gate_sigmas", c.odometry_gate_sigmas)
      .add("loop_sigma_m", c.loop_sigma_m)
      .add("loop_sigma_deg", c.loop_sigma_deg)
      .add("loop_kernel", c.loop_kernel);
  return keys;
}

LoopClosureConfig loadLoopClosureConfig(const YamlConfig& root) { return loadSection<LoopClosureConfig>(root, "loop"); }

void validate(const LoopClosureConfig& c, const std::string& file) {
  const ValueCheck check(file, "loop");
  check(c.scan_context.rings >= 1, "scan_context.rings", "must be at least 1");
  check(c.scan_context.sectors >= 2, "scan_context.sectors", "must be at least 2");
  check(c.scan_context.max_radius > 0.0, "scan_context.max_radius", "must be positive");
  for (const auto& [key, value] :
       {std::pair{"keyframe_distance", c.keyframe_distance}, std::pair{"keyframe_angle_deg", c.keyframe_angle_deg},
        std::pair{"max_rms", c.max_rms}, std::pair{"odometry_sigma_m", c.odometry_sigma_m},
        std::pair{"odometry_sigma_deg", c.odometry_sigma_deg}, std::pair{"odometry_gate_sigmas", c.odometry_gate_sigmas},
        std::pair{"loop_sigma_m", c.loop_sigma_m}, std::pair{"loop_sigma_deg", c.loop_sigma_deg},
        std::pair{"loop_kernel", c.loop_kernel}})
    check(value > 0.0, key, "must be positive");
  check(c.exclude_recent_path >= 0.0, "exclude_recent_path", "must not be negative");
  check(c.ring_key_candidates >= 1, "ring_key_candidates", "must be at least 1");
  check(c.max_descriptor_distance > 0.0 && c.max_descriptor_distance <= 1.0, "max_descriptor_distance",
        "must be in (0, 1]");
  check(c.submap_keyframes >= 0, "submap_keyframes", "must not be negative");
  check(c.min_inlier_ratio >= 0.0 && c.min_inlier_ratio <= 1.0, "min_inlier_ratio", "must be in [0, 1]");
}

}  // namespace lvslam::loop
