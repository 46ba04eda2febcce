#include "lvslam/fusion/temporal_alignment.h"

#include "lvslam/core/se3.h"

namespace lvslam::fusion {

ConstantVelocityMotion::ConstantVelocityMotion(double t0, const Eigen::Isometry3d& T_world_lidar0, double t1,
                                               const Eigen::Isometry3d& T_world_lidar1)
    : t0_(t0), t1_(t1), T0_(T_world_lidar0), T1_(T_world_lidar1) {}

Eigen::Isometry3d ConstantVelocityMotion::poseAt(double t) const {
  return interpolateAtTime(t, t0_, T0_, t1_, T1_);
}

Eigen::Isometry3d ConstantVelocityMotion::relative(double t_target, double t_source) const {
  return poseAt(t_target).inverse() * poseAt(t_source);
}

CameraTimeAligner::CameraTimeAligner(const ConstantVelocityMotion& motion, double t_camera,
                                     const Eigen::Isometry3d& T_camera_lidar)
    : motion_(motion), T_camera_world_(T_camera_lidar * motion.poseAt(t_camera).inverse()) {}

Eigen::Vector3d CameraTimeAligner::operator()(const Eigen::Vector3d& p_lidar, double t_point) const {
  return T_camera_world_ * (motion_.poseAt(t_point) * p_lidar);
}

Eigen::Vector3d CameraTimeAligner::rotate(const Eigen::Vector3d& v_lidar, double t_point) const {
  return T_camera_world_.linear() * (motion_.poseAt(t_point).linear() * v_lidar);
}

}  // namespace lvslam::fusion
