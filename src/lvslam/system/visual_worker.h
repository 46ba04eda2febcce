#pragma once
// The visual side of the dual system, run by one thread: the visual
// subsystem, fed with LiDAR depth hints for a metric start (from the latest
// raw scans); in fused mode with the fusion lines of each frame and the
// fusion framework's depths for keyframe points, in visual mode with keyframe
// depths from the raw scans (and points made from them).
#include <memory>
#include <vector>

#include "lvslam/core/calibration.h"
#include "lvslam/core/lidar_scan.h"
#include "lvslam/fusion/fusion_framework.h"
#include "lvslam/system/frame_records.h"
#include "lvslam/system/record_fields.h"
#include "lvslam/system/record_file.h"
#include "lvslam/system/system_config.h"
#include "lvslam/visual/visual_slam.h"

namespace lvslam::system {

// The image's line segments as the fusion framework takes them (raw pixels).
std::vector<fusion::ImageSegment> fusionSegments(const visual::ExtractedImage& image, const PinholeCamera& camera);

class VisualWorker {
 public:
  // Throws lvslam::Error when the calibration has no camera. With a LiDAR
  // (has_lidar) the scans given through addScan() provide depth hints.
  VisualWorker(const SystemConfig& config, const Calibration& calibration, bool has_lidar);

  // Raw scans, kept (the last two) for the depth hints of the next images.
  void addScan(std::shared_ptr<const LidarScan> scan);
  // Tracks the next camera frame, extracted (extractImage) in extract_ms.
  // Returns the keypoints (raw pixels) of a frame that became a keyframe
  // when their LiDAR depth comes from the fusion framework; else none.
  std::vector<Eigen::Vector2d> track(visual::ExtractedImage image, double extract_ms);
  // The fusion framework's answer for the frame just tracked.
  void applyFusion(const FusionAnswer& answer);

  // The records of every frame, handed over once the run has ended.
  RecordFile<VisualFrameRecord> takeFrames();
  // The record of the frame just tracked, and how many frames so far.
  const VisualFrameRecord& lastFrame() const { return *last_; }
  std::size_t frameCount() const { return frames_.size() + (last_ ? 1 : 0); }
  const visual::VisualSlam& slam() const { return slam_; }

 private:
  Calibration calibration_;
  bool use_fusion_lines_;
  bool use_keypoint_depths_;
  double hint_max_dt_;
  bool has_lidar_;
  bool depths_from_scans_;  // with a LiDAR: keyframe depths from raw points (system.keypoint_depth_source)
  double keypoint_depth_radius_px_;
  double keypoint_depth_max_dt_;  // s, deskewed raw points for keyframe depths
  bool keep_replay_observations_;  // the refinement relocates frames in their final maps
  visual::VisualSlam slam_;
  std::vector<std::shared_ptr<const LidarScan>> recent_scans_;
  // Every frame's record on disk but the last, which the fusion answer
  // still completes.
  RecordFile<VisualFrameRecord> frames_;
  std::optional<VisualFrameRecord> last_;
};

}  // namespace lvslam::system
