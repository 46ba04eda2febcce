#include "lvslam/fusion/fusion_step.h"

#include <algorithm>

#include "lvslam/fusion/lidar_bridge.h"

namespace lvslam::fusion {

FusionStep::FusionStep(const PinholeCamera& camera, const Eigen::Isometry3d& T_camera_lidar,
                       const FusionConfig& config)
    : framework_(camera, T_camera_lidar, config) {}

void FusionStep::loadScans(const lidar::LidarOdometry& odometry) {
  // Rebuilt every scan rather than appended: registration has since refined
  // the recent frames' poses, deskew and (through d_v_mean) directions.
  framework_.clearLidarScans();
  for (const lidar::FeatureFrame& frame : odometry.recentFrames())
    framework_.addLidarScan(toTimedFeatures(frame), motionOf(frame));
  const lidar::FeatureFrame& current = odometry.currentFrame();
  if (!current.points.empty()) framework_.addLidarScan(toTimedFeatures(current), motionOf(current));
}

FusionFrameOutput FusionStep::processImage(double t_camera, const std::vector<ImageSegment>& segments,
                                           lidar::LidarOdometry& odometry) const {
  FusionFrameOutput out;
  out.T_world_lidar = odometry.poseAt(t_camera);
  out.result = framework_.process(t_camera, out.T_world_lidar, segments);
  if (lidar_feedback_) out.lidar_points_changed = applyDirectionUpdates(odometry, out.result.lidar_updates);
  return out;
}

double sweepEnd(const LidarScan& scan) {
  if (!scan.has_time || scan.points.empty()) return scan.timestamp;
  float last = scan.points.front().time;
  for (const auto& p : scan.points) last = std::max(last, p.time);
  return scan.timestamp + static_cast<double>(last);
}

}  // namespace lvslam::fusion
