#include "lvslam/loop/loop_keyframe.h"

#include "lvslam/core/se3.h"

namespace lvslam::loop {

bool KeyframeSelector::isKeyframe(const Eigen::Isometry3d& T_odom_lidar, double& path_length) {
  if (!last_) {
    last_ = T_odom_lidar;
    path_length = path_at_last_ = 0.0;
    return true;
  }
  const Eigen::Isometry3d step = last_->inverse() * T_odom_lidar;
  const double moved = step.translation().norm();
  if (moved < distance_ && rotationAngle(step) < angle_rad_) return false;
  last_ = T_odom_lidar;
  path_at_last_ += moved;
  path_length = path_at_last_;
  return true;
}

}  // namespace lvslam::loop
