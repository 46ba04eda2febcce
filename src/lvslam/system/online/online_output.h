#pragma once
// The system's online output, one camera frame at a time in frame order:
// each frame's pose from that frame's records and earlier ones only, never
// revised. One strategy per mode: the LiDAR odometry (lidar), the visual
// subsystem kept continuous across its maps (visual), the fused estimator
// behind the detection module (fused), or the paper's output (ablation
// "paper-output": the visual pose while trusted, the LiDAR's chained in).
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lvslam/system/frame_records.h"
#include "lvslam/system/detection/detection_module.h"
#include "lvslam/system/online/fused_estimator.h"
#include "lvslam/system/system_config.h"

namespace lvslam::system {

struct FrameOutput {
  double t = 0.0;
  std::optional<Eigen::Isometry3d> T_world_camera;  // none: no estimate for this frame
  OutputSource source = OutputSource::kLidar;       // kVisual: vision entered this frame's pose
  std::string problem;    // the detection module's reason when vision was not admitted
  bool fused = false;     // both subsystems' factors entered this frame's pose
  std::vector<GateEvent> gated;          // factors the estimator's chi-square gate dropped
  double visual_chi_square_per_dof = -1.0;  // consistency of the accepted visual factor (-1: none)
  double lidar_noise_scale = 1.0, visual_noise_scale = 1.0;  // covariance multipliers the estimator used
  // Of T_world_camera, fused mode only: world-frame translation, then rotation.
  std::optional<Matrix6d> covariance;
  double latency_ms = 0.0;  // output wall time minus the frame's arrival
};

class OnlineOutput {
 public:
  virtual ~OnlineOutput() = default;
  // Either record may be null when the mode has no such subsystem.
  virtual FrameOutput add(const VisualFrameRecord* visual, const LidarFrameRecord* lidar) = 0;
  // A better LiDAR pose of frame `index`, already added (a later sweep
  // registered): it may improve later frames, never the frame's own output.
  virtual void lidarImproved(std::size_t /*index*/, const LidarFrameRecord& /*lidar*/) {}
  virtual std::vector<SwitchEvent> switches() const { return {}; }
  // Where each visual map sits in the output world (T_world_map per map id).
  virtual std::map<int, Eigen::Isometry3d> mapPlacements() const { return {}; }
  // The fused estimator's graph over the whole run (fused mode only), for
  // the offline refinement: call once, after the last frame.
  virtual std::optional<EstimatorGraph> takeGraph() { return std::nullopt; }
};

// `final_visual_poses`: feed the visual poses placed on the final keyframes
// (offline refinement of the visual and paper outputs) instead of as tracked.
std::unique_ptr<OnlineOutput> makeOnlineOutput(const SystemConfig& config, const Eigen::Isometry3d& T_camera_lidar,
                                               bool final_visual_poses = false);

// Health figures of one visual frame for the detection module.
VisualHealth healthOf(const VisualFrameRecord& record);

}  // namespace lvslam::system
