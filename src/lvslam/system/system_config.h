#pragma once
// Everything the dual system is configured with, one plain struct per box of
// the paper's Fig. 1, and the switches of the ablation study. Loaded from the
// sections lidar:, visual:, fusion:, detection:, estimator:, loop: and system:
// of YAML files, each section a table of keys (configKeys); absent keys keep
// their value, unknown keys and unworkable values are lvslam::Errors naming
// the file and the key. config/advanced.yaml shows every key with its default.
#include <memory>
#include <string>
#include <vector>

#include "lvslam/core/config_keys.h"
#include "lvslam/core/yaml_config.h"
#include "lvslam/fusion/fusion_config.h"
#include "lvslam/lidar/lidar_config.h"
#include "lvslam/loop/loop_config.h"
#include "lvslam/loop/loop_keyframe.h"
#include "lvslam/system/detection/detection_module.h"
#include "lvslam/system/online/fused_estimator.h"
#include "lvslam/visual/tracking/visual_slam_config.h"

namespace lvslam::system {

enum class RunMode { kLidar, kVisual, kFused };
const char* runModeName(RunMode mode);
// Throws lvslam::Error naming `where` for an unknown name.
RunMode parseRunMode(const std::string& name, const std::string& where);

// Where keyframe keypoints take their LiDAR depth from (with a LiDAR and
// visual.keypoint_depths on): the raw points of the latest sweeps, deskewed
// to the image time with the camera's motion, or the fusion framework's
// accumulated LiDAR features (fused mode only). Scans by default: they give
// the lower fused error over several scenes and seeds
// (docs/history/2026-11-fusion-sessions.md, "Fused mode over nine sequences").
enum class KeypointDepthSource { kScans, kFeatures };

struct SystemConfig {
  RunMode mode = RunMode::kFused;
  lidar::LidarOdometryConfig lidar;
  visual::VisualSlamConfig visual;
  fusion::FusionConfig fusion;
  DetectionConfig detection;
  FusedEstimatorConfig estimator;
  loop::LoopClosureConfig loop;  // LiDAR loop closure: *_refined outputs and the map only
  // Switched by --ablate only (applyAblation), never by a file.
  // The paper's output (ablation "paper-output"): the visual pose while
  // the detection module trusts it, the LiDAR's chained in otherwise.
  bool paper_output = false;
  bool fusion_lines_in_tracking = true;    // fusion lines become visual landmarks
  bool lidar_direction_refinement = true;  // d_v_mean reaches the LiDAR's linear points
  // LiDAR points this close in time to an image give its depth hints.
  double depth_hint_max_dt = 0.02;
  // A keyframe keypoint takes the LiDAR depth of features this close (pixels;
  // the features are sparse on the image, so a tight radius leaves a keyframe
  // few depths: docs/history/2026-11-fusion-sessions.md, "The dual system").
  double keypoint_depth_radius_px = 8.0;
  // From scans: raw points this close in time to a keyframe,
  // deskewed with the camera's motion, give its keypoint depths (one sweep
  // at 10 Hz; the sweep phase then never leaves a keyframe without depth).
  double keypoint_depth_max_dt = 0.1;
  KeypointDepthSource keypoint_depth_source = KeypointDepthSource::kScans;
  double map_voxel = 0.2;  // m, voxel of the exported LiDAR map (map.ply)
  // Visual poses in the output on their keyframes' poses at the end of the
  // run (final_visual_poses.h); false: each as tracked at its time.
  bool final_map_poses = true;
  // Those frames then optimised again against the final landmarks
  // (relocateInFinalMaps, final_visual_poses.h); false: only placed.
  // Visual mode and the paper's output only: the fused estimator's
  // refinement replays the frames as tracked.
  bool final_map_relocation = true;
  // One thread, fixed order: byte-identical output for the same input.
  bool deterministic = false;
  // Read the recording at the pace of its own time stamps, as a live robot
  // delivers it (latency as live; otherwise as fast as the system goes).
  bool realtime = false;
  // A saved map's keyframes to localise the run in (--map-in; never a file
  // key): the loop closure's thread tries each keyframe of the run against them.
  std::shared_ptr<const std::vector<loop::LoopKeyframe>> localize_in;
  // The records keep the loop closure's keyframes for a saved map (--map-out).
  bool keep_loop_keyframes = false;
};

// Whether the offline refinement optimises visual frames again in their
// final maps, so that each frame's tracked observations must be kept.
bool relocatesInFinalMaps(const SystemConfig& config);

// Switches off one contribution of the paper for the ablation study:
// "direction-residual" (e_dir in bundle adjustment), "lidar-direction-
// refinement" (d_v_mean), "fusion-lines" (fusion lines as visual landmarks);
// or one of lvslam's own additions, "keypoint-depths" (LiDAR depth for
// keyframe points in bundle adjustment, beyond the paper's metric start) and
// "paper-output" (the output is the visual pose itself, as in the paper,
// instead of the fused estimator).
// Throws lvslam::Error naming `where` for another name.
void applyAblation(SystemConfig& config, const std::string& name, const std::string& where);
inline const char* const kAblations[] = {"direction-residual", "lidar-direction-refinement", "fusion-lines",
                                         "keypoint-depths", "paper-output"};

// Every key of every section ("lidar.preprocess.min_range"), bound to `config`.
ConfigKeys configKeys(SystemConfig& config);
ConfigKeys configKeys(DetectionConfig& config);
ConfigKeys configKeys(FusedEstimatorConfig& config);
void validate(const DetectionConfig& config, const std::string& file);
void validate(const FusedEstimatorConfig& config, const std::string& file);

// The keys `root` (a whole file) holds, read onto `config`, then every
// section checked; errors name root's file. The mode, the ablations and the
// deterministic and realtime flags come from the command line.
void readSystemConfig(SystemConfig& config, const YamlConfig& root);
// The built-in defaults with `root`'s keys read onto them.
SystemConfig loadSystemConfig(const YamlConfig& root);
// config/advanced.yaml of the source tree (lvslam::configDir()): every key
// with its default and what it does.
std::string advancedConfigPath();
// What lvslam run and lvslam_node run with: advanced.yaml, then the user's
// file `path` (none when empty) over it.
SystemConfig loadRunConfig(const std::string& path);

}  // namespace lvslam::system
