#pragma once
// LiDAR depth residual of a point seen by a keyframe with a measured depth
// z_lidar for that keypoint (DEMO, Zhang et al. 2014 / LIMO, Graeter et al.
// 2018; ORB-SLAM2's RGB-D depth term): e = (z_c(T_cw p_w) - z_lidar) / sigma,
// with analytic Jacobians for the left SE3 pose update and the world point.
// It ties the monocular map to the metric LiDAR scale.

#include <Eigen/Core>

#include "lvslam/core/se3.h"
#include "lvslam/visual/residuals/pose_block.h"

namespace lvslam::visual {

struct PointDepth {
  // False when the point is not in front of the camera or input is not finite.
  static bool evaluate(const Eigen::Matrix3d& R_cw, const Eigen::Vector3d& t_cw, const Eigen::Vector3d& p_w,
                       double depth, double inv_sigma, double& residual, Eigen::Matrix<double, 1, 6>* J_pose,
                       Eigen::Matrix<double, 1, 3>* J_point) {
    const Eigen::Vector3d p_c = R_cw * p_w + t_cw;
    if (!(p_c.z() > 1e-6) || !p_c.allFinite()) return false;
    residual = inv_sigma * (p_c.z() - depth);
    if (J_pose) {
      // e_z^T d p_c / d(rho, phi) = e_z^T [I, -[p_c]x] for T <- exp(delta) T.
      *J_pose << 0.0, 0.0, inv_sigma, inv_sigma * p_c.y(), -inv_sigma * p_c.x(), 0.0;
    }
    if (J_point) *J_point = inv_sigma * R_cw.row(2);
    return true;
  }
};

}  // namespace lvslam::visual
