#pragma once
// The fusion framework between the LiDAR subsystem's two steps, one LiDAR
// scan and its camera frames at a time (paper, Fig. 2 and "Modification of
// the linear direction"):
//   odometry.prepare(scan); step.loadScans(odometry);
//   for each camera time t_{j+1} in the scan's interval: step.processImage(t, segments, odometry);
//   odometry.registerScan();
// Each camera frame sees the current and the last four scans aligned to its
// time; its d_v_mean updates reach the LiDAR's linear points before registration.
#include <vector>

#include "lvslam/core/lidar_scan.h"
#include "lvslam/fusion/fusion_framework.h"
#include "lvslam/lidar/lidar_odometry.h"

namespace lvslam::fusion {

struct FusionFrameOutput {
  FusionResult result;
  Eigen::Isometry3d T_world_lidar = Eigen::Isometry3d::Identity();  // LiDAR pose used at the camera time
  std::size_t lidar_points_changed = 0;                             // linear points given d_v_mean
};

class FusionStep {
 public:
  FusionStep(const PinholeCamera& camera, const Eigen::Isometry3d& T_camera_lidar, const FusionConfig& config);

  // After odometry.prepare(scan): the prepared frame and the recent
  // registered ones become the accumulated scans, each placed with the
  // subsystem's latest pose and direction estimates.
  void loadScans(const lidar::LidarOdometry& odometry);

  // One camera frame at absolute time t_camera: features aligned to it with
  // the LiDAR pose there (constant velocity around the prepared frame),
  // fusion lines, and the direction feedback applied to `odometry`.
  FusionFrameOutput processImage(double t_camera, const std::vector<ImageSegment>& segments,
                                 lidar::LidarOdometry& odometry) const;

  // Ablation: with the feedback off, processImage() leaves the LiDAR's
  // linear points as they are (the updates are still reported).
  void setLidarFeedback(bool on) { lidar_feedback_ = on; }

  const FusionFramework& framework() const { return framework_; }

 private:
  FusionFramework framework_;
  bool lidar_feedback_ = true;
};

// End of a sweep in absolute time: the last point's time (the time stamp
// itself without per-point times). Camera frames up to it belong to the scan.
double sweepEnd(const LidarScan& scan);

}  // namespace lvslam::fusion
