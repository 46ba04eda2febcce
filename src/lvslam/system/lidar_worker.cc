#include "lvslam/system/lidar_worker.h"

#include <algorithm>
#include <cmath>

#include "lvslam/core/se3.h"
#include "lvslam/system/online/pose_information.h"
#include "lvslam/system/stopwatch.h"

namespace lvslam::system {

LidarWorker::LidarWorker(const SystemConfig& config, const Calibration& calibration)
    : odometry_(config.lidar),
      keypoint_depth_radius_px_(config.keypoint_depth_radius_px),
      keypoint_depths_from_features_(config.keypoint_depth_source == KeypointDepthSource::kFeatures &&
                                     config.visual.modules.use_keypoint_depths),
      map_(config.map_voxel),
      keep_loop_keyframes_(config.keep_loop_keyframes) {
  if (config.mode == RunMode::kFused && calibration.camera) {
    fusion_.emplace(*calibration.camera, calibration.T_camera_lidar, config.fusion);
    fusion_->setLidarFeedback(config.lidar_direction_refinement);
    extrinsic_check_.emplace(*calibration.camera, config.fusion);
    // Camera-time poses are only worth handing back when the visual side uses them.
    if (config.visual.modules.use_lidar_pose_priors) T_lidar_camera_ = calibration.T_camera_lidar.inverse();
  }
  if (config.loop.enabled) {
    keyframe_selector_.emplace(config.loop.keyframe_distance, config.loop.keyframe_angle_deg * M_PI / 180.0);
    loop_closure_ = std::make_unique<LoopClosureWorker>(config.loop, config.lidar.registration, !config.deterministic,
                                                        config.localize_in);
  }
}

void LidarWorker::offerKeyframe(const lidar::OdometryResult& result) {
  double path_length = 0.0;
  if (!loop_closure_ || !keyframe_selector_->isKeyframe(result.T_world_lidar, path_length)) return;
  map_keyframe_starts_.push_back(map_.points().size());
  loop_closure_->add({result.timestamp, result.T_world_lidar, odometry_.currentFrame().points, path_length});
}

std::optional<loop::LoopClosureResult> LidarWorker::finishLoopClosure() {
  if (!loop_closure_) return std::nullopt;
  return loop_closure_->finish();
}

std::vector<loop::LoopKeyframe> LidarWorker::takeLoopKeyframes() {
  return loop_closure_ && keep_loop_keyframes_ ? loop_closure_->takeKeyframes() : std::vector<loop::LoopKeyframe>{};
}

void LidarWorker::addScan(const LidarScan& scan) {
  registerPending();
  const Stopwatch watch;
  odometry_.prepare(scan);
  if (fusion_) fusion_->loadScans(odometry_);
  pending_prepare_ms_ = watch.ms();
  scan_pending_ = true;
}

FusionAnswer LidarWorker::addFrame(double t, const std::vector<fusion::ImageSegment>& segments) {
  LidarFrameRecord record;
  record.t = t;
  FusionAnswer answer;
  fusion_frame_ = false;
  if (fusion_ && scan_pending_) {
    const Stopwatch watch;
    fusion::FusionFrameOutput out = fusion_->processImage(t, segments, odometry_);
    fusion_frame_ = true;
    T_world_lidar_last_frame_ = out.T_world_lidar;
    record.lidar_features = out.result.lidar_features;
    record.lidar_points_refined = out.lidar_points_changed;
    for (const fusion::FusionLine& line : out.result.lines) record.fusion_lines.push_back({line.A, line.B});
    answer.result = std::move(out.result);
    checkExtrinsic(t, segments);
    record.fusion_ms = watch.ms();  // the check included: it is fusion work
  }
  closeFinishedFrames();  // the previous frame's fusion answer is complete
  frames_waiting_.push_back(first_open_ + open_frames_.size());
  open_frames_.push_back(std::move(record));
  answer.lidar_camera_poses.swap(new_camera_poses_);
  return answer;
}

// A frame no scan will pose or interpolate again, whose fusion answer is
// complete (any but the last added), goes to disk.
void LidarWorker::closeFinishedFrames() {
  std::size_t first_pending = first_open_ + open_frames_.size();
  for (const std::size_t index : frames_waiting_) first_pending = std::min(first_pending, index);
  for (const std::size_t index : frames_provisional_) first_pending = std::min(first_pending, index);
  while (open_frames_.size() > 1 && first_open_ < first_pending) {
    frames_.push_back(open_frames_.front());
    open_frames_.pop_front();
    ++first_open_;
  }
}

RecordFile<LidarFrameRecord> LidarWorker::takeFrames() {
  for (const LidarFrameRecord& frame : open_frames_) frames_.push_back(frame);
  first_open_ += open_frames_.size();
  open_frames_.clear();
  return std::move(frames_);
}

// Every window's verdict goes to stats.json (extrinsic_check). No warning
// line yet: on correct calibrations the simulated scenes' own offsets
// between LiDAR line features and image edges are as large as the errors to
// be found, so the test would warn about a correct calibration
// (docs/benchmarks.md, "The extrinsic check").
void LidarWorker::checkExtrinsic(double t, const std::vector<fusion::ImageSegment>& segments) {
  recordExtrinsicVerdict(extrinsic_check_->addFrame(
      scans_.size(), t, fusion_->framework().featuresInCamera(T_world_lidar_last_frame_), segments));
}

void LidarWorker::recordExtrinsicVerdict(const std::optional<fusion::ExtrinsicVerdict>& verdict) {
  if (verdict) extrinsic_verdicts_.push_back(*verdict);
}

std::vector<double> LidarWorker::keypointDepths(const std::vector<Eigen::Vector2d>& keyframe_keypoints) {
  if (!fusion_frame_ || keyframe_keypoints.empty() || open_frames_.empty()) return {};
  const Stopwatch watch;
  std::vector<double> depths =
      fusion_->framework().pointDepths(T_world_lidar_last_frame_, keyframe_keypoints, keypoint_depth_radius_px_);
  open_frames_.back().fusion_ms += watch.ms();
  open_frames_.back().keypoint_depths = depthCount(depths);
  return depths;
}

void LidarWorker::finish() {
  registerPending();
  if (extrinsic_check_) recordExtrinsicVerdict(extrinsic_check_->finish());
  frames_provisional_.clear();  // no later sweep: their within-sweep pose stands
  poseWaitingFrames(true, false, false);
}

// A frame is posed as soon as the sweep covering its time is registered,
// by the registered pose and the sweep's motion (what the deskew uses): the
// online output goes on from there. When the next sweep is registered too,
// the frame's pose is interpolated between the two, which is better and
// replaces it in the record (for the estimator's window and the offline
// refinement; the online output already out is not revised). At the end,
// frames after the last sweep are extrapolated with the constant velocity.
void LidarWorker::poseWaitingFrames(bool extrapolate, bool reliable, bool prior_worthy) {
  if (scan_trajectory_.empty()) return;
  const StampedPose& last = scan_trajectory_.back();
  const double sweep = scan_trajectory_.size() >= 2 ? last.t - scan_trajectory_[scan_trajectory_.size() - 2].t : 0.0;
  // A pose moved on from the sweep by its motion carries the velocity's
  // error over the time moved as well as the registration's.
  const auto moved = [&](double t) {
    const PseudoInverse seen = pseudoInverse(last_information_);
    if (seen.rank == 0) return Matrix6d(Matrix6d::Zero());
    return informationOn(seen.range, seen.inverse + odometry_.motionCovarianceAt(t));
  };
  const auto pose = [&](std::size_t index, const Eigen::Isometry3d& T_odom_lidar, bool measured = true,
                        const std::optional<Matrix6d>& information = std::nullopt) {
    LidarFrameRecord& frame = openFrame(index);
    frame.T_odom_lidar = T_odom_lidar;
    frame.pose_reliable = reliable && measured;
    frame.information = information ? *information : last_information_;
    frame.degenerate = last_degenerate_;
    frame.registration = scan_trajectory_.size();
    if (on_frame_posed_) on_frame_posed_(index, frame);
  };
  std::vector<std::size_t> still_provisional;
  for (const std::size_t index : frames_provisional_) {
    const LidarFrameRecord& frame = openFrame(index);
    if (frame.t > last.t || scan_trajectory_.size() < 2) {
      still_provisional.push_back(index);
      continue;
    }
    const StampedPose& before = scan_trajectory_[scan_trajectory_.size() - 2];
    pose(index, interpolateAtTime(frame.t, before.t, before.T_world_frame, last.t, last.T_world_frame));
    if (prior_worthy && T_lidar_camera_) new_camera_poses_.push_back({frame.t, *frame.T_odom_lidar * *T_lidar_camera_});
  }
  frames_provisional_ = std::move(still_provisional);
  std::vector<std::size_t> still_waiting;
  for (const std::size_t index : frames_waiting_) {
    const double t = openFrame(index).t;
    if (scan_trajectory_.size() >= 3 && t < last.t) {
      // No registered sweep covers the frame (a drop-out, or a sweep the
      // odometry rejected; the first sweep, whose length was unknown, posed
      // nothing): the pose between the sweeps around the gap is a guess for
      // the LiDAR's own output, not a measurement for the estimator.
      const StampedPose& before = scan_trajectory_[scan_trajectory_.size() - 2];
      pose(index, interpolateAtTime(t, before.t, before.T_world_frame, last.t, last.T_world_frame), false);
    } else if (t <= last.t + sweep && sweep > 0.0) {
      pose(index, odometry_.poseAt(t), true, moved(t));
      frames_provisional_.push_back(index);
    } else if (extrapolate) {  // only at the end, where `reliable` is false
      pose(index, odometry_.poseAt(t), true, moved(t));
    } else {
      still_waiting.push_back(index);
    }
  }
  frames_waiting_ = std::move(still_waiting);
  closeFinishedFrames();
}

void LidarWorker::registerPending() {
  if (!scan_pending_) return;
  scan_pending_ = false;
  const Stopwatch watch;
  const lidar::OdometryResult result = odometry_.registerScan();
  ScanRecord record;
  record.t = result.timestamp;
  record.status = lidar::statusName(result.status);
  record.features = result.features;
  for (const lidar::FeaturePoint& point : odometry_.currentFrame().points)
    ++record.features_per_class[static_cast<std::size_t>(point.cls)];
  record.correspondences = result.correspondences;
  record.iterations = result.iterations;
  record.prepare_ms = pending_prepare_ms_;
  record.register_ms = watch.ms();
  scans_.push_back(record);
  if (result.status == lidar::OdometryStatus::kRejected) return;  // the frames wait for the next scan
  last_information_ = result.information;
  last_degenerate_ = result.status == lidar::OdometryStatus::kDegenerate;
  scan_trajectory_.push_back({result.timestamp, result.T_world_lidar});
  const bool lost = result.status == lidar::OdometryStatus::kLost;
  if (!lost) {
    offerKeyframe(result);
    map_.add(odometry_.currentFrame());
  }
  // A frame next to a lost scan has no pose worth a factor; next to a scan
  // blind along some direction (held at the prediction there), none worth
  // a visual prior, whose covariance is isotropic.
  const bool whole = !lost && result.status != lidar::OdometryStatus::kDegenerate;
  poseWaitingFrames(false, !lost && !previous_scan_lost_, whole && previous_scan_whole_);
  previous_scan_lost_ = lost;
  previous_scan_whole_ = whole;
}

}  // namespace lvslam::system
