#pragma once
// The LiDAR side of the dual system, run by one thread: the LiDAR subsystem
// and, in fused mode, the fusion framework between its two steps (paper,
// Fig. 2). Scans and camera frames arrive in time order; a scan is
// registered when the next one arrives (or at finish()), after the fusion
// framework has seen every camera frame of its sweep and refined its linear
// points. Each camera frame gets the LiDAR pose at its time once the sweep
// covering that time is registered, and a better one interpolated between
// two sweeps once the next is; in fused mode that one, in the camera frame,
// goes back to the visual side with a later frame's answer.
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "lvslam/core/calibration.h"
#include "lvslam/fusion/extrinsic_check.h"
#include "lvslam/fusion/fusion_step.h"
#include "lvslam/lidar/lidar_odometry.h"
#include "lvslam/system/frame_records.h"
#include "lvslam/system/record_fields.h"
#include "lvslam/system/record_file.h"
#include "lvslam/system/lidar_map_export.h"
#include "lvslam/system/offline/loop_closure_worker.h"
#include "lvslam/system/system_config.h"

namespace lvslam::system {

class LidarWorker {
 public:
  // Fusion runs when the mode is fused and the calibration has a camera.
  LidarWorker(const SystemConfig& config, const Calibration& calibration);

  void addScan(const LidarScan& scan);
  // The next camera frame at time t. Its line segments (fused mode, raw
  // pixels) go through the fusion framework: fusion lines (camera frame at
  // t) come back, and the camera poses of earlier frames that became known.
  FusionAnswer addFrame(double t, const std::vector<fusion::ImageSegment>& segments);
  // Whether the frame just added wants LiDAR depth for the keypoints of a
  // keyframe (fused mode, system.keypoint_depth_source: features), and that
  // depth (NaN where none), from the features accumulated at its time.
  bool answersKeypointDepths() const { return fusion_ && keypoint_depths_from_features_; }
  std::vector<double> keypointDepths(const std::vector<Eigen::Vector2d>& keyframe_keypoints);
  // The sweep of the last scan has ended (every camera frame of it was
  // added): registers it now rather than when the next scan arrives.
  void endSweep() { registerPending(); }
  // Registers the last scan: call once after the last scan and frame.
  void finish();

  // Called (on this worker's thread) when a frame's LiDAR pose becomes known
  // (within its sweep), and again when it is interpolated between that sweep
  // and the next, with the frame's index: the online output goes on from
  // the first call; the second improves the estimator's window.
  using FramePosed = std::function<void(std::size_t index, const LidarFrameRecord& record)>;
  void onFramePosed(FramePosed callback) { on_frame_posed_ = std::move(callback); }

  // The records of every scan and camera frame, handed over after finish().
  RecordFile<ScanRecord> takeScans() { return std::move(scans_); }
  RecordFile<LidarFrameRecord> takeFrames();
  const LidarMapExport& map() const { return map_; }
  // T_odom_lidar at each registered scan's time stamp.
  const Trajectory& scanTrajectory() const { return scan_trajectory_; }
  // With loop closure on (loop.enabled): registered scans become keyframes
  // by the path travelled and go to the loop closure's own thread. After
  // finish(), its result (none when off), and per keyframe the index of the
  // first map() point added from its scan on.
  std::optional<loop::LoopClosureResult> finishLoopClosure();
  // The loop closure's keyframes, moved out after finishLoopClosure(), when
  // the configuration keeps them (keep_loop_keyframes); else none.
  std::vector<loop::LoopKeyframe> takeLoopKeyframes();
  const std::vector<std::size_t>& mapKeyframeStarts() const { return map_keyframe_starts_; }
  // The extrinsic check's verdict per window of frames (fused mode).
  const std::vector<fusion::ExtrinsicVerdict>& extrinsicVerdicts() const { return extrinsic_verdicts_; }

 private:
  void registerPending();
  // reliable: worth a LiDAR factor; prior_worthy (implies reliable): worth a
  // visual pose prior too.
  void poseWaitingFrames(bool extrapolate, bool reliable, bool prior_worthy);
  void offerKeyframe(const lidar::OdometryResult& result);
  void checkExtrinsic(double t, const std::vector<fusion::ImageSegment>& segments);
  void recordExtrinsicVerdict(const std::optional<fusion::ExtrinsicVerdict>& verdict);

  lidar::LidarOdometry odometry_;
  std::optional<fusion::FusionStep> fusion_;
  double keypoint_depth_radius_px_;
  bool keypoint_depths_from_features_;
  bool fusion_frame_ = false;  // the last frame went through the fusion framework
  Eigen::Isometry3d T_world_lidar_last_frame_ = Eigen::Isometry3d::Identity();  // the fusion framework's, at the last frame
  std::optional<fusion::ExtrinsicCheck> extrinsic_check_;
  std::vector<fusion::ExtrinsicVerdict> extrinsic_verdicts_;
  LidarMapExport map_;
  bool scan_pending_ = false;
  double pending_prepare_ms_ = 0.0;
  std::vector<std::size_t> frames_waiting_;      // frames whose pose needs the pending scan
  std::vector<std::size_t> frames_provisional_;  // posed within their sweep, to be interpolated
  // Fused mode with visual.lidar_pose_priors: camera poses go to the visual side.
  std::optional<Eigen::Isometry3d> T_lidar_camera_;
  Trajectory new_camera_poses_;                      // for the next answer
  bool previous_scan_lost_ = false;
  bool previous_scan_whole_ = true;  // registered in every direction
  Matrix6d last_information_ = Matrix6d::Zero();  // of the last registered scan
  bool last_degenerate_ = false;                  // likewise: blind along some direction
  FramePosed on_frame_posed_;
  RecordFile<ScanRecord> scans_;
  // Frames [0, first_open_) on disk; from first_open_ on in memory, as long
  // as a pose, an interpolation or the fusion answer may still change them.
  RecordFile<LidarFrameRecord> frames_;
  std::deque<LidarFrameRecord> open_frames_;
  std::size_t first_open_ = 0;
  LidarFrameRecord& openFrame(std::size_t index) { return open_frames_[index - first_open_]; }
  void closeFinishedFrames();
  Trajectory scan_trajectory_;
  std::optional<loop::KeyframeSelector> keyframe_selector_;
  std::unique_ptr<LoopClosureWorker> loop_closure_;
  bool keep_loop_keyframes_ = false;
  std::vector<std::size_t> map_keyframe_starts_;
};

}  // namespace lvslam::system
