#pragma once
// Loop closure over a run's LiDAR keyframes: each keyframe gets its Scan
// Context, a candidate among the older keyframes and, when the descriptors
// agree, a geometric verification; accepted loops become robust edges of
// the global pose graph, whose solution moves every keyframe. A verified
// loop must also agree with the odometry within its drift over the path
// between the two keyframes. Single
// threaded and deterministic: the order of keyframes fixes every figure
// (system/ runs it on its own thread).
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/lidar/lidar_config.h"
#include "lvslam/loop/global_pose_graph.h"
#include "lvslam/loop/loop_config.h"
#include "lvslam/loop/loop_keyframe.h"
#include "lvslam/loop/loop_verification.h"
#include "lvslam/loop/map_localizer.h"
#include "lvslam/loop/scan_context.h"

namespace lvslam::loop {

// The best candidate of a keyframe and what became of it.
struct LoopCandidateRecord {
  int query = 0, candidate = 0;  // keyframe indices
  double query_t = 0.0, candidate_t = 0.0;
  double ring_key_distance = 0.0;
  double descriptor_distance = 0.0;
  double yaw = 0.0;  // radians, from the descriptor
  bool verified = false;  // reached the ICP (descriptor distance low enough)
  LoopVerification verification;
  std::string reason;       // why rejected, empty when accepted
  double graph_weight = 0.0;  // accepted: the kernel's weight in the solved graph
};

struct LoopClosureResult {
  std::vector<double> keyframe_times;
  std::vector<double> path_lengths;                       // the odometry's path from the first keyframe
  std::vector<Eigen::Isometry3d> T_odom_lidar;            // the odometry's keyframe poses
  std::vector<Eigen::Isometry3d> T_odom_lidar_corrected;  // after the graph
  std::vector<LoopCandidateRecord> candidates;
  // Whose the keyframe poses are: "lidar" (the LiDAR odometry, as the run
  // made them) or "fused" (regateWithOdometry on the fused trajectory).
  std::string odometry = "lidar";
  bool solved = false;
  // With a saved map to localise in (--map-in): the run's keyframes tried
  // against it, and where the run's odometry frame sits in the map's.
  std::optional<MapLocalization> map_localization;
  std::size_t accepted() const;
};

// The loop closure again over the same keyframes and the candidates the ICP
// verified, with other poses for the keyframes (fused mode: the fused
// estimator's, one per keyframe of `live`): each verified candidate is gated
// against them afresh, and the graph solved from them. The keyframes keep
// their path lengths.
LoopClosureResult regateWithOdometry(const LoopClosureResult& live, const std::vector<Eigen::Isometry3d>& T_odom_lidar,
                                     const std::string& odometry, const LoopClosureConfig& config);

// Empty when `offset` (what a match says beyond what the odometry says)
// lies within the odometry's drift over `path` metres (odometry_sigma_m and
// _deg per root metre, times odometry_gate_sigmas), else why not.
std::string offByDrift(const Eigen::Isometry3d& offset, double path, const LoopClosureConfig& config);

class LoopClosure {
 public:
  LoopClosure(const LoopClosureConfig& config, const lidar::RegistrationConfig& registration);

  // Adds the next keyframe (in time order); true when it closed a loop.
  bool addKeyframe(LoopKeyframe keyframe);
  // The graph over every keyframe so far, solved from the odometry poses.
  LoopClosureResult solve() const;

  std::size_t keyframeCount() const { return keyframes_.size(); }
  // Moves the keyframes out: call after the last solve().
  std::vector<LoopKeyframe> takeKeyframes() { return std::move(keyframes_); }
  const std::vector<LoopCandidateRecord>& candidates() const { return candidates_; }

 private:
  LoopClosureConfig config_;
  lidar::RegistrationConfig registration_;
  std::vector<LoopKeyframe> keyframes_;
  std::vector<ScanContext> descriptors_;
  std::vector<double> path_lengths_;
  std::vector<LoopCandidateRecord> candidates_;
};

}  // namespace lvslam::loop
