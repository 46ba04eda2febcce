#pragma once
// The correction that makes fused mode's output (with output fusion on): the
// LiDAR odometry's camera pose at every camera time, moved toward the fused pose
// (pose_fusion.h) while the detection module trusts vision. The correction
// lives in the camera frame and changes by bounded steps per frame, so the
// output has no jump when vision joins or leaves; the LiDAR odometry itself
// is continuous, so nothing has to be chained or re-anchored at a switch.
// World = the LiDAR odometry frame.
#include <cmath>
#include <optional>

#include <Eigen/Geometry>

namespace lvslam::system {

class OutputCorrection {
 public:
  // The correction changes by at most max_m and max_deg per frame.
  OutputCorrection(double max_step_m, double max_step_deg)
      : max_step_m_(max_step_m), max_step_rad_(max_step_deg * M_PI / 180.0) {}

  // The output pose of the next frame: T_odom_camera_lidar moved toward
  // `target` (none: toward the LiDAR pose itself).
  Eigen::Isometry3d add(const Eigen::Isometry3d& T_odom_camera_lidar, const std::optional<Eigen::Isometry3d>& target);

 private:
  double max_step_m_, max_step_rad_;
  // The correction: the output's camera in the LiDAR's camera.
  Eigen::Isometry3d T_lidar_output_ = Eigen::Isometry3d::Identity();
};

}  // namespace lvslam::system
