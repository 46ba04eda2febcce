#include "lvslam/system/system_config.h"

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

void applyAblation(SystemConfig& config, const std::string& name, const std::string& where) {
  if (name == "direction-residual")
    config.visual.visual.local_window.ba.use_direction_residual = false;
  else if (name == "lidar-direction-refinement")
    config.lidar_direction_refinement = false;
  else if (name == "fusion-lines")
    config.fusion_lines_in_tracking = false;
  else if (name == "keypoint-depths")
    config.visual.visual.use_keypoint_depths = false;
  else if (name == "paper-output")
    config.paper_output = true;
  else
    throw Error(where, "unknown ablation '" + name +
                           "' (direction-residual, lidar-direction-refinement, fusion-lines, keypoint-depths or "
                           "paper-output)");
}

DetectionConfig loadDetectionConfig(const YamlConfig& n) {
  n.requireKnownKeys({"min_tracked_points", "min_tracked_lines", "min_inlier_ratio", "min_brightness",
                      "max_brightness", "min_contrast", "frames_to_recover", "rejoin_step_m", "rejoin_step_deg"});
  DetectionConfig c;
  c.min_tracked_points = n.getInt("min_tracked_points", c.min_tracked_points);
  c.min_tracked_lines = n.getInt("min_tracked_lines", c.min_tracked_lines);
  c.min_inlier_ratio = n.getDouble("min_inlier_ratio", c.min_inlier_ratio);
  c.min_brightness = n.getDouble("min_brightness", c.min_brightness);
  c.max_brightness = n.getDouble("max_brightness", c.max_brightness);
  c.min_contrast = n.getDouble("min_contrast", c.min_contrast);
  c.frames_to_recover = n.getInt("frames_to_recover", c.frames_to_recover);
  c.rejoin_step_m = n.getDouble("rejoin_step_m", c.rejoin_step_m);
  c.rejoin_step_deg = n.getDouble("rejoin_step_deg", c.rejoin_step_deg);
  if (c.min_tracked_points < 0 || c.min_tracked_lines < 0) n.fail("tracked minima must not be negative");
  if (!(c.min_inlier_ratio >= 0.0 && c.min_inlier_ratio <= 1.0)) n.fail("min_inlier_ratio must be in [0, 1]");
  if (!(c.min_brightness < c.max_brightness)) n.fail("need min_brightness < max_brightness");
  if (c.frames_to_recover < 1) n.fail("frames_to_recover must be at least 1");
  if (!(c.rejoin_step_m >= 0.0 && c.rejoin_step_deg >= 0.0)) n.fail("rejoin steps must not be negative");
  return c;
}

FusedEstimatorConfig loadEstimatorConfig(const YamlConfig& n) {
  n.requireKnownKeys({"window_s", "visual_pixel_sigma", "lidar_drift_m", "lidar_drift_deg", "visual_drift_m",
                      "visual_drift_deg", "motion_accel",
                      "motion_angular_accel_deg", "gate_accept_after", "huber_delta", "max_iterations"});
  FusedEstimatorConfig c;
  c.window_s = n.getDouble("window_s", c.window_s);
  c.visual_pixel_sigma = n.getDouble("visual_pixel_sigma", c.visual_pixel_sigma);
  c.lidar_drift_m = n.getDouble("lidar_drift_m", c.lidar_drift_m);
  c.lidar_drift_deg = n.getDouble("lidar_drift_deg", c.lidar_drift_deg);
  c.visual_drift_m = n.getDouble("visual_drift_m", c.visual_drift_m);
  c.visual_drift_deg = n.getDouble("visual_drift_deg", c.visual_drift_deg);
  c.motion_accel = n.getDouble("motion_accel", c.motion_accel);
  c.motion_angular_accel_deg = n.getDouble("motion_angular_accel_deg", c.motion_angular_accel_deg);
  c.gate_accept_after = n.getInt("gate_accept_after", c.gate_accept_after);
  c.huber_delta = n.getDouble("huber_delta", c.huber_delta);
  c.max_iterations = n.getInt("max_iterations", c.max_iterations);
  if (!(c.window_s >= 0.0)) n.at("window_s").fail("must not be negative");
  if (!(c.visual_pixel_sigma > 0.0)) n.at("visual_pixel_sigma").fail("must be positive");
  if (!(c.lidar_drift_m >= 0.0 && c.lidar_drift_deg >= 0.0)) n.fail("lidar_drift_m and lidar_drift_deg must be >= 0");
  if (!(c.visual_drift_m >= 0.0 && c.visual_drift_deg >= 0.0)) n.fail("visual_drift_m and visual_drift_deg must be >= 0");
  if (!(c.motion_accel > 0.0 && c.motion_angular_accel_deg > 0.0))
    n.fail("motion_accel and motion_angular_accel_deg must be positive");
  if (c.gate_accept_after < 0) n.at("gate_accept_after").fail("must not be negative");
  if (!(c.huber_delta > 0.0)) n.at("huber_delta").fail("must be positive");
  if (c.max_iterations < 1) n.at("max_iterations").fail("must be at least 1");
  return c;
}

SystemConfig loadSystemConfig(const YamlConfig& root) {
  // A misspelt section would silently keep all its defaults.
  root.requireKnownKeys({"lidar", "visual", "fusion", "detection", "estimator", "loop", "system"});
  SystemConfig c;
  if (root.find("lidar")) c.lidar = lidar::loadLidarOdometryConfig(root);
  if (const auto v = root.find("visual")) c.visual.visual = visual::loadVisualConfig(*v);
  c.fusion = fusion::loadFusionConfig(root);
  if (const auto d = root.find("detection")) c.detection = loadDetectionConfig(*d);
  if (const auto f = root.find("estimator")) c.estimator = loadEstimatorConfig(*f);
  c.loop = loop::loadLoopClosureConfig(root);
  if (const auto s = root.find("system")) {
    s->requireKnownKeys({"fusion_lines_in_tracking", "lidar_direction_refinement", "depth_hint_max_dt",
                         "keypoint_depth_radius_px", "keypoint_depth_max_dt", "keypoint_depth_source",
                         "map_voxel", "final_map_poses", "final_map_relocation"});
    c.fusion_lines_in_tracking = s->getBool("fusion_lines_in_tracking", c.fusion_lines_in_tracking);
    c.lidar_direction_refinement = s->getBool("lidar_direction_refinement", c.lidar_direction_refinement);
    c.depth_hint_max_dt = s->getDouble("depth_hint_max_dt", c.depth_hint_max_dt);
    c.keypoint_depth_radius_px = s->getDouble("keypoint_depth_radius_px", c.keypoint_depth_radius_px);
    c.keypoint_depth_max_dt = s->getDouble("keypoint_depth_max_dt", c.keypoint_depth_max_dt);
    c.map_voxel = s->getDouble("map_voxel", c.map_voxel);
    c.final_map_poses = s->getBool("final_map_poses", c.final_map_poses);
    c.final_map_relocation = s->getBool("final_map_relocation", c.final_map_relocation);
    if (const auto source = s->find("keypoint_depth_source")) {
      const std::string name = source->asString();
      if (name == "scans")
        c.keypoint_depth_source = KeypointDepthSource::kScans;
      else if (name == "features")
        c.keypoint_depth_source = KeypointDepthSource::kFeatures;
      else
        source->fail("must be 'scans' or 'features', not '" + name + "'");
    }
    if (!(c.keypoint_depth_radius_px > 0.0)) s->at("keypoint_depth_radius_px").fail("must be positive");
    if (!(c.depth_hint_max_dt > 0.0)) s->at("depth_hint_max_dt").fail("must be positive");
    if (!(c.keypoint_depth_max_dt > 0.0)) s->at("keypoint_depth_max_dt").fail("must be positive");
    if (!(c.map_voxel > 0.0)) s->at("map_voxel").fail("must be positive");
  }
  return c;
}

}  // namespace lvslam::system
