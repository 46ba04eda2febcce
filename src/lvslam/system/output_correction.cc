#include "lvslam/system/output_correction.h"

#include "lvslam/core/se3.h"

namespace lvslam::system {

Eigen::Isometry3d OutputCorrection::add(const Eigen::Isometry3d& T_odom_camera_lidar,
                                             const std::optional<Eigen::Isometry3d>& target) {
  const Eigen::Isometry3d T_wanted =
      target ? T_odom_camera_lidar.inverse() * *target : Eigen::Isometry3d::Identity();
  T_lidar_output_ = boundedStep(T_lidar_output_, T_wanted, max_step_m_, max_step_rad_);
  return T_odom_camera_lidar * T_lidar_output_;
}

}  // namespace lvslam::system
