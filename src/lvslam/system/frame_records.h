#pragma once
// What each subsystem's thread records per camera frame and per scan. Each
// thread writes only its own records (no sharing); the output is assembled
// from them in frame order afterwards.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/fusion/fusion_framework.h"
#include "lvslam/lidar/feature_point.h"
#include "lvslam/visual/tracking/visual_frame_result.h"

namespace lvslam::system {

// Keyframe keypoints with a LiDAR depth among `depths` (NaN where none).
inline std::size_t depthCount(const std::vector<double>& depths) {
  return static_cast<std::size_t>(std::count_if(depths.begin(), depths.end(), [](double z) { return std::isfinite(z); }));
}

// The visual thread's view of camera frame `index`.
struct VisualFrameRecord {
  double t = 0.0;
  visual::VisualFrameResult result;
  // The pose (and the map's first view, with result.initial_reference) on
  // the map's keyframes as they stand at the end of the run
  // (placeOnFinalKeyframes, final_visual_poses.h); none when the frame has no pose.
  std::optional<Eigen::Isometry3d> T_world_camera_final;
  std::optional<Eigen::Isometry3d> initial_reference_final;
  int fusion_lines_added = 0;  // landmarks created or given d_fu
  // Keyframe keypoints given a LiDAR depth from the raw scans (the default
  // source; LidarFrameRecord counts those from the fusion framework's features).
  std::size_t keypoint_depths = 0;
  double extract_ms = 0.0;  // features, on the extraction thread
  double hints_ms = 0.0, track_ms = 0.0, fusion_apply_ms = 0.0;
};

// A fusion line kept for the line map: endpoints in the camera frame at t.
struct CameraLine {
  Eigen::Vector3d A = Eigen::Vector3d::Zero(), B = Eigen::Vector3d::Zero();
};

// The fusion framework's answer for one camera frame.
struct FusionAnswer {
  fusion::FusionResult result;
  std::vector<double> keypoint_depths;  // per keyframe keypoint, NaN where none
  // T_odom_camera of the earlier frames whose LiDAR pose became known since
  // the previous answer (registered, not lost, scans on both sides).
  Trajectory lidar_camera_poses;
};

// The LiDAR thread's view of camera frame `index`.
struct LidarFrameRecord {
  double t = 0.0;
  std::optional<Eigen::Isometry3d> T_odom_lidar;  // after the scan around t was registered
  bool pose_reliable = false;  // interpolated between two scans registered without loss
  // Of T_odom_lidar: the information of the later of those scans' registration
  // (lidar::OdometryResult::information, body-frame perturbation); of a pose
  // moved on from its sweep by the sweep's motion, less by the velocity's
  // error over the time moved (lidar::LidarOdometry::motionCovarianceAt).
  Matrix6d information = Matrix6d::Zero();
  // That scan's registration was blind along some direction (held at the
  // prediction there): it did not hold the odometry to its map.
  bool degenerate = false;
  std::size_t registration = 0;  // which registered scan the pose comes from (counted from 1)
  std::vector<CameraLine> fusion_lines;
  std::size_t lidar_features = 0;   // accumulated features the fusion framework saw
  std::size_t lidar_points_refined = 0;  // linear points given d_v_mean
  std::size_t keypoint_depths = 0;       // keyframe keypoints given a LiDAR depth
  double fusion_ms = 0.0;
};

// A LiDAR record as the online output took it: a frame's first pose, or a
// better one for a frame already out (an improvement).
struct LidarInputEvent {
  std::size_t index = 0;
  bool improvement = false;
  LidarFrameRecord record;  // without its fusion lines
};

struct ScanRecord {
  double t = 0.0;
  std::string status;
  std::size_t features = 0, correspondences = 0;
  std::array<std::size_t, lidar::kFeatureClassCount> features_per_class{};  // ground .. vertex
  int iterations = 0;
  double prepare_ms = 0.0, register_ms = 0.0;
};

}  // namespace lvslam::system
