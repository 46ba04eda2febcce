#pragma once
// Every tunable of loop closure (the `loop:` section of a YAML file): when a
// LiDAR scan becomes a keyframe, how places are recognised and verified, and
// how the global pose graph weighs its edges.
#include <string>

#include "lvslam/core/config_keys.h"
#include "lvslam/core/yaml_config.h"
#include "lvslam/loop/scan_context.h"

namespace lvslam::loop {

struct LoopClosureConfig {
  bool enabled = true;
  // A registered scan becomes a keyframe once the odometry moved this far
  // (or turned this much) since the last keyframe.
  double keyframe_distance = 1.0;  // metres
  double keyframe_angle_deg = 15.0;
  ScanContextConfig scan_context;
  // Keyframes within this much odometry path of the query are not loop
  // candidates (they are the same pass, tied by odometry already).
  double exclude_recent_path = 15.0;  // metres
  int ring_key_candidates = 10;       // nearest by ring key, then compared whole
  double max_descriptor_distance = 0.25;  // Scan Context distance to try verification
  // Verification: the query's features registered by the multi-metric ICP
  // onto its candidate and the keyframes next to it (this many on each side),
  // with the correspondence distance shrinking through these thresholds.
  int submap_keyframes = 2;
  double max_rms = 0.06;           // metres, noise-weighted RMS residual at the last threshold
  double min_inlier_ratio = 0.4;   // correspondences per query feature at the last threshold
  // Global pose graph. Odometry edges: the odometry's drift, a standard
  // deviation per square root of the path between keyframes.
  double odometry_sigma_m = 0.03;    // metres per sqrt(m)
  double odometry_sigma_deg = 0.3;   // degrees per sqrt(m)
  // A verified loop further off the odometry than this many of those
  // standard deviations (over the path between its keyframes) is rejected.
  double odometry_gate_sigmas = 5.0;
  // Loop edges: the ICP's own covariance plus this floor (the ICP's figure
  // counts every point as independent).
  double loop_sigma_m = 0.05;
  double loop_sigma_deg = 0.5;
  // Cauchy kernel on the whitened loop residual: a loop this many sigmas
  // off the rest of the graph keeps half its weight.
  double loop_kernel = 3.0;
};

// The keys of the `loop:` section ("scan_context.rings"), bound to `config`.
ConfigKeys configKeys(LoopClosureConfig& config);
// Reads the `loop` section of the file (absent: defaults). Unknown keys or
// values that cannot work throw lvslam::Error naming the file and the key.
LoopClosureConfig loadLoopClosureConfig(const YamlConfig& root);
// Throws lvslam::Error(file, "key 'loop.<key>': ...") on values that cannot work.
void validate(const LoopClosureConfig& config, const std::string& file);

}  // namespace lvslam::loop
