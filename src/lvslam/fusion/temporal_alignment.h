#pragma once
// Temporal alignment (paper, "Preprocessing"): the camera time stamp is the
// reference; each LiDAR point captured at its own time is moved to the camera
// time with a relative pose interpolated at constant velocity.
#include <Eigen/Geometry>

namespace lvslam::fusion {

// The LiDAR's motion over a short interval: T_world_lidar at two times,
// interpolated (slerp + lerp) between them and extrapolated outside at the
// same constant velocity.
class ConstantVelocityMotion {
 public:
  ConstantVelocityMotion(double t0, const Eigen::Isometry3d& T_world_lidar0, double t1,
                         const Eigen::Isometry3d& T_world_lidar1);

  Eigen::Isometry3d poseAt(double t) const;
  // T_lidar(t_target)_lidar(t_source): maps a point measured in the LiDAR frame
  // at t_source into the LiDAR frame at t_target.
  Eigen::Isometry3d relative(double t_target, double t_source) const;

 private:
  double t0_, t1_;
  Eigen::Isometry3d T0_, T1_;
};

// Moves LiDAR points, each measured at its own time, into the camera frame at
// one camera time: p_camera = T_camera_lidar * T_lidar(t_camera)_lidar(t_point) * p_lidar.
class CameraTimeAligner {
 public:
  CameraTimeAligner(const ConstantVelocityMotion& motion, double t_camera, const Eigen::Isometry3d& T_camera_lidar);
  Eigen::Vector3d operator()(const Eigen::Vector3d& p_lidar, double t_point) const;
  // For a direction (normal or line direction) measured at t_point.
  Eigen::Vector3d rotate(const Eigen::Vector3d& v_lidar, double t_point) const;

 private:
  ConstantVelocityMotion motion_;
  Eigen::Isometry3d T_camera_world_;  // the camera at t_camera, through the LiDAR pose then
};

}  // namespace lvslam::fusion
