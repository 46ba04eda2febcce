#include "lvslam/visual/visual_config.h"

#include <algorithm>
#include <initializer_list>
#include <string>

#include "lvslam/core/error.h"

namespace lvslam::visual {

namespace {

void rejectUnknownKeys(const YamlConfig& node, std::initializer_list<const char*> known) {
  if (!node.node().IsMap()) node.fail("must be a map");
  for (const auto& item : node.node()) {
    const std::string key = item.first.as<std::string>();
    if (std::none_of(known.begin(), known.end(), [&](const char* k) { return key == k; })) {
      node.fail("unknown key '" + key + "'");
    }
  }
}

void loadFeatures(const YamlConfig& n, FeatureExtractorConfig& c) {
  if (const auto orb = n.find("orb")) {
    rejectUnknownKeys(*orb, {"max_features", "scale_factor", "num_levels", "fast_threshold", "grid_cell_size",
                             "candidate_factor"});
    c.orb.max_features = orb->getInt("max_features", c.orb.max_features);
    c.orb.scale_factor = orb->getDouble("scale_factor", c.orb.scale_factor);
    c.orb.num_levels = orb->getInt("num_levels", c.orb.num_levels);
    c.orb.fast_threshold = orb->getInt("fast_threshold", c.orb.fast_threshold);
    c.orb.grid_cell_size = orb->getInt("grid_cell_size", c.orb.grid_cell_size);
    c.orb.candidate_factor = orb->getDouble("candidate_factor", c.orb.candidate_factor);
  }
  if (const auto lines = n.find("lines")) {
    rejectUnknownKeys(*lines, {"enabled", "scale", "density_threshold", "min_length_ratio", "max_lines",
                               "descriptor_octave"});
    c.extract_lines = lines->getBool("enabled", c.extract_lines);
    c.lines.scale = lines->getDouble("scale", c.lines.scale);
    c.lines.density_threshold = lines->getDouble("density_threshold", c.lines.density_threshold);
    c.lines.min_length_ratio = lines->getDouble("min_length_ratio", c.lines.min_length_ratio);
    c.lines.max_lines = lines->getInt("max_lines", c.lines.max_lines);
    c.lines.descriptor_octave = lines->getInt("descriptor_octave", c.lines.descriptor_octave);
  }
}

void loadOptimisation(const YamlConfig& n, VisualConfig& c) {
  if (const auto pose = n.find("pose")) {
    rejectUnknownKeys(*pose, {"rounds", "iterations_per_round", "chi2_point", "chi2_line", "min_inliers"});
    c.pose.rounds = pose->getInt("rounds", c.pose.rounds);
    c.pose.iterations_per_round = pose->getInt("iterations_per_round", c.pose.iterations_per_round);
    c.pose.chi2_point = pose->getDouble("chi2_point", c.pose.chi2_point);
    c.pose.chi2_line = pose->getDouble("chi2_line", c.pose.chi2_line);
    c.pose.min_inliers = pose->getInt("min_inliers", c.pose.min_inliers);
    if (c.pose.rounds < 1 || c.pose.iterations_per_round < 1) pose->fail("rounds and iterations must be >= 1");
  }
  if (const auto ba = n.find("bundle_adjustment")) {
    rejectUnknownKeys(*ba, {"window_size", "first_stage_iterations", "second_stage_iterations", "direction_weight",
                            "direction_huber_delta", "use_direction_residual"});
    LocalWindowConfig& w = c.local_window;
    const int window = ba->getInt("window_size", static_cast<int>(w.window_size));
    if (window < 2) ba->fail("window_size must be >= 2");
    w.window_size = static_cast<size_t>(window);
    w.ba.first_stage_iterations = ba->getInt("first_stage_iterations", w.ba.first_stage_iterations);
    w.ba.second_stage_iterations = ba->getInt("second_stage_iterations", w.ba.second_stage_iterations);
    w.ba.direction_weight = ba->getDouble("direction_weight", w.ba.direction_weight);
    w.ba.direction_huber_delta = ba->getDouble("direction_huber_delta", w.ba.direction_huber_delta);
    w.ba.use_direction_residual = ba->getBool("use_direction_residual", w.ba.use_direction_residual);
    if (w.ba.first_stage_iterations < 1 || w.ba.second_stage_iterations < 0) ba->fail("iterations out of range");
    if (!(w.ba.direction_weight >= 0.0) || !(w.ba.direction_huber_delta > 0.0)) ba->fail("direction terms must be positive");
  }
}

}  // namespace

VisualConfig loadVisualConfig(const YamlConfig& section) {
  VisualConfig c;
  rejectUnknownKeys(section, {"orb", "lines", "pose", "bundle_adjustment", "initializer", "keypoint_depths",
                             "lidar_pose_priors", "map_reuse", "keyframes"});
  loadFeatures(section, c.features);
  loadOptimisation(section, c);
  if (const auto init = section.find("initializer")) {
    rejectUnknownKeys(*init, {"min_parallax_deg", "min_triangulated", "min_depth_hints"});
    c.initializer.min_parallax_deg = init->getDouble("min_parallax_deg", c.initializer.min_parallax_deg);
    c.initializer.min_triangulated = init->getInt("min_triangulated", c.initializer.min_triangulated);
    c.initializer.min_depth_hints = init->getInt("min_depth_hints", c.initializer.min_depth_hints);
  }
  if (const auto depths = section.find("keypoint_depths")) {
    rejectUnknownKeys(*depths, {"enabled", "sigma_ratio", "huber_delta"});
    BundleAdjustmentConfig& ba = c.local_window.ba;
    c.use_keypoint_depths = depths->getBool("enabled", c.use_keypoint_depths);
    ba.depth_sigma_ratio = depths->getDouble("sigma_ratio", ba.depth_sigma_ratio);
    ba.depth_huber_delta = depths->getDouble("huber_delta", ba.depth_huber_delta);
    if (!(ba.depth_sigma_ratio > 0.0) || !(ba.depth_huber_delta > 0.0))
      depths->fail("sigma_ratio and huber_delta must be positive");
  }
  if (const auto priors = section.find("lidar_pose_priors")) {
    rejectUnknownKeys(*priors, {"enabled", "sigma_m", "sigma_deg", "huber_delta", "map_correction"});
    BundleAdjustmentConfig& ba = c.local_window.ba;
    c.use_lidar_pose_priors = priors->getBool("enabled", c.use_lidar_pose_priors);
    ba.prior_sigma_m = priors->getDouble("sigma_m", ba.prior_sigma_m);
    ba.prior_sigma_deg = priors->getDouble("sigma_deg", ba.prior_sigma_deg);
    ba.prior_huber_delta = priors->getDouble("huber_delta", ba.prior_huber_delta);
    if (!(ba.prior_sigma_m > 0.0) || !(ba.prior_sigma_deg > 0.0) || !(ba.prior_huber_delta > 0.0))
      priors->fail("sigma_m, sigma_deg and huber_delta must be positive");
    if (const auto correction = priors->find("map_correction")) {
      rejectUnknownKeys(*correction,
                        {"every_keyframes", "window_keyframes", "min_covisibility", "sigma_m", "sigma_deg", "iterations"});
      MapCorrectionConfig& m = c.map_correction;
      m.every_keyframes = correction->getInt("every_keyframes", m.every_keyframes);
      m.window_keyframes = correction->getInt("window_keyframes", m.window_keyframes);
      m.min_covisibility = correction->getInt("min_covisibility", m.min_covisibility);
      m.graph.edge_sigma_m = correction->getDouble("sigma_m", m.graph.edge_sigma_m);
      m.graph.edge_sigma_deg = correction->getDouble("sigma_deg", m.graph.edge_sigma_deg);
      m.graph.max_iterations = correction->getInt("iterations", m.graph.max_iterations);
      if (m.every_keyframes < 0 || m.window_keyframes < 0 || m.min_covisibility < 1 || !(m.graph.edge_sigma_m > 0.0) ||
          !(m.graph.edge_sigma_deg > 0.0) || m.graph.max_iterations < 1) {
        correction->fail(
            "every_keyframes >= 0, window_keyframes >= 0, min_covisibility >= 1, iterations >= 1 and positive sigmas "
            "required");
      }
    }
  }
  PoseGraphConfig& graph = c.map_correction.graph;
  graph.prior_sigma_m = c.local_window.ba.prior_sigma_m;
  graph.prior_sigma_deg = c.local_window.ba.prior_sigma_deg;
  graph.prior_huber_delta = c.local_window.ba.prior_huber_delta;
  if (const auto reuse = section.find("map_reuse")) {
    rejectUnknownKeys(*reuse, {"radius_depths", "max_angle_deg", "max_keyframes", "min_age_keyframes"});
    LocalKeyframeConfig& m = c.local_map;
    m.nearby_radius_depths = reuse->getDouble("radius_depths", m.nearby_radius_depths);
    m.nearby_max_angle_deg = reuse->getDouble("max_angle_deg", m.nearby_max_angle_deg);
    const int n = reuse->getInt("max_keyframes", static_cast<int>(m.nearby_max));
    const int age = reuse->getInt("min_age_keyframes", static_cast<int>(m.nearby_min_age));
    if (!(m.nearby_radius_depths >= 0.0) || !(m.nearby_max_angle_deg > 0.0 && m.nearby_max_angle_deg <= 180.0) ||
        n < 0 || age < 0) {
      reuse->fail("radius_depths >= 0, max_angle_deg in (0, 180], max_keyframes >= 0 and min_age_keyframes >= 0 required");
    }
    m.nearby_max = static_cast<std::size_t>(n);
    m.nearby_min_age = static_cast<std::size_t>(age);
  }
  if (const auto kf = section.find("keyframes")) {
    rejectUnknownKeys(*kf, {"tracked_ratio", "min_tracked", "min_interval", "max_interval", "min_inliers"});
    KeyframePolicy& k = c.keyframes;
    k.tracked_ratio = kf->getDouble("tracked_ratio", k.tracked_ratio);
    k.min_tracked = kf->getInt("min_tracked", k.min_tracked);
    k.min_interval = kf->getInt("min_interval", k.min_interval);
    k.max_interval = kf->getInt("max_interval", k.max_interval);
    k.min_inliers = kf->getInt("min_inliers", k.min_inliers);
    if (!(k.tracked_ratio > 0.0 && k.tracked_ratio <= 1.0)) kf->at("tracked_ratio").fail("must be in (0, 1]");
    if (k.min_tracked < 0) kf->at("min_tracked").fail("must be >= 0");
    if (k.min_inliers < 0) kf->at("min_inliers").fail("must be >= 0");
    if (k.min_interval < 1 || k.max_interval < k.min_interval)
      kf->fail("1 <= min_interval <= max_interval required, got " + std::to_string(k.min_interval) + " and " +
               std::to_string(k.max_interval));
  }
  // The extractors and the initializer validate the rest when constructed;
  // do it now so a bad file fails at load time, naming the file.
  try {
    OrbExtractor orb(c.features.orb);
    LineExtractor lines(c.features.lines);
    TwoViewInitializer init(c.initializer, PinholeIntrinsics{});
  } catch (const Error& e) {
    section.fail(e.what());
  }
  return c;
}

}  // namespace lvslam::visual
