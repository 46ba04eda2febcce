#include "lvslam/system/system_config.h"

#include <filesystem>

#include "lvslam/core/config_dir.h"
#include "lvslam/core/error.h"

namespace lvslam::system {

const char* runModeName(RunMode mode) {
  switch (mode) {
    case RunMode::kLidar: return "lidar";
    case RunMode::kVisual: return "visual";
    case RunMode::kFused: return "fused";
  }
  return "?";
}

RunMode parseRunMode(const std::string& name, const std::string& where) {
  if (name == "lidar") return RunMode::kLidar;
  if (name == "visual") return RunMode::kVisual;
  if (name == "fused") return RunMode::kFused;
  throw Error(where, "unknown mode '" + name + "' (lidar, visual or fused)");
}

bool relocatesInFinalMaps(const SystemConfig& config) {
  const bool replays_final_poses =
      config.mode == RunMode::kVisual || (config.mode == RunMode::kFused && config.paper_output);
  return replays_final_poses && config.final_map_poses && config.final_map_relocation;
}

void applyAblation(SystemConfig& config, const std::string& name, const std::string& where) {
  if (name == "direction-residual")
    config.visual.modules.local_window.ba.use_direction_residual = false;
  else if (name == "lidar-direction-refinement")
    config.lidar_direction_refinement = false;
  else if (name == "fusion-lines")
    config.fusion_lines_in_tracking = false;
  else if (name == "keypoint-depths")
    config.visual.modules.use_keypoint_depths = false;
  else if (name == "paper-output")
    config.paper_output = true;
  else
    throw Error(where, "unknown ablation '" + name +
                           "' (direction-residual, lidar-direction-refinement, fusion-lines, keypoint-depths or "
                           "paper-output)");
}

ConfigKeys configKeys(DetectionConfig& c) {
  ConfigKeys keys;
  keys.add("min_tracked_points", c.min_tracked_points)
      .add("min_tracked_lines", c.min_tracked_lines)
      .add("min_inlier_ratio", c.min_inlier_ratio)
      .add("min_brightness", c.min_brightness)
      .add("max_brightness", c.max_brightness)
      .add("min_contrast", c.min_contrast)
      .add("frames_to_recover", c.frames_to_recover)
      .add("rejoin_step_m", c.rejoin_step_m)
      .add("rejoin_step_deg", c.rejoin_step_deg);
  return keys;
}

void validate(const DetectionConfig& c, const std::string& file) {
  const ValueCheck check(file, "detection");
  check(c.min_tracked_points >= 0, "min_tracked_points", "must not be negative");
  check(c.min_tracked_lines >= 0, "min_tracked_lines", "must not be negative");
  check(c.min_inlier_ratio >= 0.0 && c.min_inlier_ratio <= 1.0, "min_inlier_ratio", "must be in [0, 1]");
  check(c.min_brightness < c.max_brightness, "min_brightness", "need min_brightness < max_brightness");
  check(c.frames_to_recover >= 1, "frames_to_recover", "must be at least 1");
  check(c.rejoin_step_m >= 0.0, "rejoin_step_m", "must not be negative");
  check(c.rejoin_step_deg >= 0.0, "rejoin_step_deg", "must not be negative");
}

// One line per key (and per check below): a new setting of the estimator
// is a line here, one there and one in config/advanced.yaml.
ConfigKeys configKeys(FusedEstimatorConfig& c) {
  ConfigKeys keys;
  keys.add("window_s", c.window_s);
  keys.add("visual_pixel_sigma", c.visual_pixel_sigma);
  keys.add("lidar_drift_m", c.lidar_drift_m);
  keys.add("lidar_drift_deg", c.lidar_drift_deg);
  keys.add("visual_drift_m", c.visual_drift_m);
  keys.add("visual_drift_deg", c.visual_drift_deg);
  keys.add("motion_accel", c.motion_accel);
  keys.add("motion_angular_accel_deg", c.motion_angular_accel_deg);
  keys.add("gate_accept_after", c.gate_accept_after);
  keys.add("huber_delta", c.huber_delta);
  keys.add("max_iterations", c.max_iterations);
  return keys;
}

void validate(const FusedEstimatorConfig& c, const std::string& file) {
  const ValueCheck check(file, "estimator");
  check(c.window_s >= 0.0, "window_s", "must not be negative");
  check(c.visual_pixel_sigma > 0.0, "visual_pixel_sigma", "must be positive");
  check(c.lidar_drift_m >= 0.0, "lidar_drift_m", "must not be negative");
  check(c.lidar_drift_deg >= 0.0, "lidar_drift_deg", "must not be negative");
  check(c.visual_drift_m >= 0.0, "visual_drift_m", "must not be negative");
  check(c.visual_drift_deg >= 0.0, "visual_drift_deg", "must not be negative");
  check(c.motion_accel > 0.0, "motion_accel", "must be positive");
  check(c.motion_angular_accel_deg > 0.0, "motion_angular_accel_deg", "must be positive");
  check(c.gate_accept_after >= 0, "gate_accept_after", "must not be negative");
  check(c.huber_delta > 0.0, "huber_delta", "must be positive");
  check(c.max_iterations >= 1, "max_iterations", "must be at least 1");
}

namespace {

// The `system:` section: SystemConfig's own settings.
ConfigKeys systemKeys(SystemConfig& c) {
  ConfigKeys keys;
  keys.add("depth_hint_max_dt", c.depth_hint_max_dt)
      .add("keypoint_depth_radius_px", c.keypoint_depth_radius_px)
      .add("keypoint_depth_max_dt", c.keypoint_depth_max_dt)
      .add("keypoint_depth_source", c.keypoint_depth_source,
           {{"scans", KeypointDepthSource::kScans}, {"features", KeypointDepthSource::kFeatures}})
      .add("map_voxel", c.map_voxel)
      .add("final_map_poses", c.final_map_poses)
      .add("final_map_relocation", c.final_map_relocation);
  return keys;
}

void validateSystem(const SystemConfig& c, const std::string& file) {
  const ValueCheck check(file, "system");
  check(c.depth_hint_max_dt > 0.0, "depth_hint_max_dt", "must be positive");
  check(c.keypoint_depth_radius_px > 0.0, "keypoint_depth_radius_px", "must be positive");
  check(c.keypoint_depth_max_dt > 0.0, "keypoint_depth_max_dt", "must be positive");
  check(c.map_voxel > 0.0, "map_voxel", "must be positive");
}

}  // namespace

ConfigKeys configKeys(SystemConfig& c) {
  ConfigKeys keys;
  keys.add("lidar", lidar::configKeys(c.lidar))
      .add("visual", visual::configKeys(c.visual))
      .add("fusion", fusion::configKeys(c.fusion))
      .add("detection", configKeys(c.detection))
      .add("estimator", configKeys(c.estimator))
      .add("loop", loop::configKeys(c.loop))
      .add("system", systemKeys(c));
  return keys;
}

void readSystemConfig(SystemConfig& config, const YamlConfig& root) {
  configKeys(config).read(root);
  const std::string& file = root.file();
  lidar::validate(config.lidar, file);
  visual::validate(config.visual, file);
  fusion::validate(config.fusion, file);
  validate(config.detection, file);
  validate(config.estimator, file);
  loop::validate(config.loop, file);
  validateSystem(config, file);
}

SystemConfig loadSystemConfig(const YamlConfig& root) {
  SystemConfig config;
  readSystemConfig(config, root);
  return config;
}

std::string advancedConfigPath() { return configDir() + "/advanced.yaml"; }

SystemConfig loadRunConfig(const std::string& path) {
  SystemConfig config;
  // The built-in defaults are advanced.yaml's numbers (a test holds them
  // equal), so a binary that cannot see the file runs the same.
  if (std::filesystem::is_regular_file(advancedConfigPath()))
    readSystemConfig(config, YamlConfig::loadFile(advancedConfigPath()));
  if (!path.empty()) readSystemConfig(config, YamlConfig::loadFile(path));
  return config;
}

}  // namespace lvslam::system
