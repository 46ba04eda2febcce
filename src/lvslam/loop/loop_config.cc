#include "lvslam/loop/loop_config.h"

namespace lvslam::loop {

namespace {

ScanContextConfig loadScanContextConfig(const YamlConfig& n) {
  n.requireKnownKeys({"rings", "sectors", "max_radius", "height_offset"});
  ScanContextConfig c;
  c.rings = n.getInt("rings", c.rings);
  c.sectors = n.getInt("sectors", c.sectors);
  c.max_radius = n.getDouble("max_radius", c.max_radius);
  c.height_offset = n.getDouble("height_offset", c.height_offset);
  if (c.rings < 1) n.at("rings").fail("must be at least 1");
  if (c.sectors < 2) n.at("sectors").fail("must be at least 2");
  if (!(c.max_radius > 0.0)) n.at("max_radius").fail("must be positive");
  return c;
}

void requirePositive(const YamlConfig& n, const std::string& key, double value) {
  if (!(value > 0.0)) n.at(key).fail("must be positive");
}

}  // namespace

LoopClosureConfig loadLoopClosureConfig(const YamlConfig& root) {
  LoopClosureConfig c;
  const auto found = root.find("loop");
  if (!found) return c;
  const YamlConfig& n = *found;
  n.requireKnownKeys({"enabled", "keyframe_distance", "keyframe_angle_deg", "scan_context", "exclude_recent_path",
                      "ring_key_candidates", "max_descriptor_distance", "submap_keyframes", "max_rms",
                      "min_inlier_ratio", "odometry_sigma_m", "odometry_sigma_deg", "odometry_gate_sigmas", "loop_sigma_m",
                      "loop_sigma_deg", "loop_kernel"});
  c.enabled = n.getBool("enabled", c.enabled);
  c.keyframe_distance = n.getDouble("keyframe_distance", c.keyframe_distance);
  c.keyframe_angle_deg = n.getDouble("keyframe_angle_deg", c.keyframe_angle_deg);
  if (const auto sc = n.find("scan_context")) c.scan_context = loadScanContextConfig(*sc);
  c.exclude_recent_path = n.getDouble("exclude_recent_path", c.exclude_recent_path);
  c.ring_key_candidates = n.getInt("ring_key_candidates", c.ring_key_candidates);
  c.max_descriptor_distance = n.getDouble("max_descriptor_distance", c.max_descriptor_distance);
  c.submap_keyframes = n.getInt("submap_keyframes", c.submap_keyframes);
  c.max_rms = n.getDouble("max_rms", c.max_rms);
  c.min_inlier_ratio = n.getDouble("min_inlier_ratio", c.min_inlier_ratio);
  c.odometry_sigma_m = n.getDouble("odometry_sigma_m", c.odometry_sigma_m);
  c.odometry_sigma_deg = n.getDouble("odometry_sigma_deg", c.odometry_sigma_deg);
  c.odometry_gate_sigmas = n.getDouble("odometry_gate_sigmas", c.odometry_gate_sigmas);
  c.loop_sigma_m = n.getDouble("loop_sigma_m", c.loop_sigma_m);
  c.loop_sigma_deg = n.getDouble("loop_sigma_deg", c.loop_sigma_deg);
  c.loop_kernel = n.getDouble("loop_kernel", c.loop_kernel);
  for (const char* key : {"keyframe_distance", "keyframe_angle_deg", "max_rms", "odometry_sigma_m",
                          "odometry_sigma_deg", "odometry_gate_sigmas", "loop_sigma_m", "loop_sigma_deg", "loop_kernel"})
    if (n.has(key)) requirePositive(n, key, n.at(key).asDouble());
  if (!(c.exclude_recent_path >= 0.0)) n.at("exclude_recent_path").fail("must not be negative");
  if (c.ring_key_candidates < 1) n.at("ring_key_candidates").fail("must be at least 1");
  if (!(c.max_descriptor_distance > 0.0 && c.max_descriptor_distance <= 1.0))
    n.at("max_descriptor_distance").fail("must be in (0, 1]");
  if (c.submap_keyframes < 0) n.at("submap_keyframes").fail("must not be negative");
  if (!(c.min_inlier_ratio >= 0.0 && c.min_inlier_ratio <= 1.0)) n.at("min_inlier_ratio").fail("must be in [0, 1]");
  return c;
}

}  // namespace lvslam::loop
