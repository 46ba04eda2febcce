#pragma once
// A LiDAR keyframe of the loop closure: a registered scan kept whole (its
// features in the LiDAR frame), chosen by the distance or angle travelled
// since the previous one, so memory grows with the path, not with time.
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/lidar/feature_point.h"

namespace lvslam::loop {

struct LoopKeyframe {
  double t = 0.0;
  Eigen::Isometry3d T_odom_lidar = Eigen::Isometry3d::Identity();  // the odometry's estimate
  std::vector<lidar::FeaturePoint> points;                         // LiDAR frame at t
  double path_length = 0.0;  // odometry path from the first keyframe, metres
};

class KeyframeSelector {
 public:
  KeyframeSelector(double distance, double angle_rad) : distance_(distance), angle_rad_(angle_rad) {}

  // True when a scan at this pose is a keyframe (the first one always);
  // `path_length` is then the keyframe's path from the first.
  bool isKeyframe(const Eigen::Isometry3d& T_odom_lidar, double& path_length);

 private:
  double distance_, angle_rad_;
  std::optional<Eigen::Isometry3d> last_;
  double path_at_last_ = 0.0;
};

}  // namespace lvslam::loop
