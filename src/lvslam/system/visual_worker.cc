#include "lvslam/system/visual_worker.h"

#include <optional>

#include "lvslam/core/error.h"
#include "lvslam/visual/geometry/surface_depth.h"
#include "lvslam/system/lidar_depth_hints.h"
#include "lvslam/system/stopwatch.h"

namespace lvslam::system {

namespace {

const PinholeCamera& requireCamera(const Calibration& calibration) {
  if (!calibration.camera) throw Error("visual subsystem", "the recording has no camera calibration");
  return *calibration.camera;
}

// The camera's motion from the previous frame to this one, when both were
// tracked in the same map: it deskews the LiDAR points of the depth hints.
std::optional<CameraMotion> motionFromPrevious(const std::optional<VisualFrameRecord>& previous,
                                               const visual::VisualFrameResult& now) {
  if (!previous || !now.pose_valid) return std::nullopt;
  const visual::VisualFrameResult& before = previous->result;
  if (!before.pose_valid || before.map_id != now.map_id) return std::nullopt;
  return CameraMotion{before.timestamp, now.T_world_camera.inverse() * before.T_world_camera};
}

// Keyframe depths from raw points, deskewed to the image time, are good
// enough to make points straight from them (ORB-SLAM2's RGB-D close points),
// which keeps tracking alive through turns where two-view triangulation lacks
// parallax. The fusion framework's depths from accumulated features are not
// (points made from them cost fused accuracy): with those, they stay BA depth
// terms (docs/history/2026-11-fusion-sessions.md, "Points from keyframe depths").
visual::VisualSlamConfig visualSlamConfig(const SystemConfig& config, bool depths_from_scans) {
  visual::VisualSlamConfig c = config.visual;
  c.triangulation.create_depth_points = depths_from_scans;
  c.depth_radius_px = config.keypoint_depth_radius_px;
  return c;
}

}  // namespace

VisualWorker::VisualWorker(const SystemConfig& config, const Calibration& calibration, bool has_lidar)
    : calibration_(calibration),
      use_fusion_lines_(config.fusion_lines_in_tracking),
      use_keypoint_depths_(config.visual.modules.use_keypoint_depths),
      hint_max_dt_(config.depth_hint_max_dt),
      has_lidar_(has_lidar),
      depths_from_scans_(has_lidar && config.visual.modules.use_keypoint_depths &&
                         (config.mode == RunMode::kVisual ||
                          config.keypoint_depth_source == KeypointDepthSource::kScans)),
      keypoint_depth_radius_px_(config.keypoint_depth_radius_px),
      keypoint_depth_max_dt_(config.keypoint_depth_max_dt),
      keep_replay_observations_(relocatesInFinalMaps(config)),
      slam_(visualSlamConfig(config, depths_from_scans_), requireCamera(calibration)) {}

void VisualWorker::addScan(std::shared_ptr<const LidarScan> scan) {
  recent_scans_.push_back(std::move(scan));
  if (recent_scans_.size() > 2) recent_scans_.erase(recent_scans_.begin());
}

std::vector<Eigen::Vector2d> VisualWorker::track(visual::ExtractedImage image, double extract_ms) {
  VisualFrameRecord record;
  record.t = image.timestamp;
  record.extract_ms = extract_ms;
  // With a LiDAR every frame is told its hints, none before the first scan,
  // so that the visual subsystem passes over a frame whose hints reach too
  // few keypoints as a map's first view (at most max_unhinted_references
  // times in a row, VisualSlamConfig; then it starts without metric depth).
  if (slam_.needsDepthHints() && has_lidar_) {
    const Stopwatch watch;
    slam_.setDepthHints(lidarDepthHints(recent_scans_, image.timestamp, calibration_, hint_max_dt_));
    record.hints_ms = watch.ms();
  }
  const Stopwatch watch;
  record.result = slam_.track(std::move(image));
  record.track_ms = watch.ms();
  if (depths_from_scans_ && record.result.pose_valid && slam_.currentIsKeyframe()) {
    // The raw points of the latest sweeps, deskewed with the camera's own
    // motion (visual mode has no LiDAR odometry to accumulate features with).
    // Without that motion only the points measured close to the image time
    // are safe.
    const Stopwatch depth_watch;
    const std::optional<CameraMotion> motion = motionFromPrevious(last_, record.result);
    const double max_dt = motion ? keypoint_depth_max_dt_ : hint_max_dt_;
    const PinholeCamera& camera = *calibration_.camera;
    const std::vector<double> depths =
        visual::surfaceDepths(lidarDepthHints(recent_scans_, record.t, calibration_, max_dt, motion),
                              slam_.keypointPixels(), keypoint_depth_radius_px_, camera.width(), camera.height());
    record.keypoint_depths = depthCount(depths);
    slam_.setKeypointDepths(depths);
    record.hints_ms += depth_watch.ms();
  }
  // A frame's inliers (about 7 kB) are kept for the whole run only when the
  // refinement will optimise the frame again on them.
  if (!keep_replay_observations_) record.result.replay.observations = {};
  if (last_) frames_.push_back(*last_);
  last_ = std::move(record);
  // Fused mode with depths from features: the fusion framework answers.
  if (!depths_from_scans_ && use_keypoint_depths_ && slam_.currentIsKeyframe()) return slam_.keypointPixels();
  return {};
}

std::vector<fusion::ImageSegment> fusionSegments(const visual::ExtractedImage& image, const PinholeCamera& camera) {
  std::vector<fusion::ImageSegment> segments;
  for (const visual::ImageLineSegment& s : visual::rawLineSegments(image.features, camera))
    segments.push_back({s.start, s.end});
  return segments;
}

void VisualWorker::applyFusion(const FusionAnswer& answer) {
  if (!last_ || !last_->result.pose_valid) return;
  const Stopwatch watch;
  if (!answer.keypoint_depths.empty()) slam_.setKeypointDepths(answer.keypoint_depths);
  for (const StampedPose& pose : answer.lidar_camera_poses) slam_.addLidarPose(pose.t, pose.T_world_frame);
  int added = 0;
  if (use_fusion_lines_)
    for (const fusion::FusionLine& line : answer.result.lines)
      added += slam_.addFusionLine(static_cast<int>(line.segment_index), line.A, line.B, line.direction) >= 0 ? 1 : 0;
  last_->fusion_lines_added = added;
  last_->fusion_apply_ms = watch.ms();
}

RecordFile<VisualFrameRecord> VisualWorker::takeFrames() {
  if (last_) frames_.push_back(*last_);
  last_.reset();
  return std::move(frames_);
}

}  // namespace lvslam::system
