#pragma once
// Point reprojection residual e = sqrt_info (pi(K, T_cw p_w) - x) (ORB-SLAM /
// Structure PLP point edge), with analytic Jacobians for the left SE3 pose
// update and the world point.

#include <Eigen/Core>

#include "lvslam/core/se3.h"
#include "lvslam/visual/residuals/pose_block.h"

namespace lvslam::visual {

struct PointReprojection {
  // False when the point is not in front of the camera or input is not finite.
  static bool evaluate(const Eigen::Matrix3d& R_cw, const Eigen::Vector3d& t_cw,
                       const Eigen::Vector3d& p_w, const Eigen::Vector2d& observed,
                       const PinholeIntrinsics& K, double sqrt_info, Eigen::Vector2d& residual,
                       Eigen::Matrix<double, 2, 6>* J_pose, Eigen::Matrix<double, 2, 3>* J_point) {
    const Eigen::Vector3d p_c = R_cw * p_w + t_cw;
    if (!(p_c.z() > 1e-6) || !p_c.allFinite()) return false;
    const double iz = 1.0 / p_c.z();
    residual = sqrt_info * Eigen::Vector2d(K.fx * p_c.x() * iz + K.cx - observed.x(),
                                           K.fy * p_c.y() * iz + K.cy - observed.y());
    if (!J_pose && !J_point) return true;
    Eigen::Matrix<double, 2, 3> J_proj;
    J_proj << K.fx * iz, 0.0, -K.fx * p_c.x() * iz * iz, 0.0, K.fy * iz, -K.fy * p_c.y() * iz * iz;
    J_proj *= sqrt_info;
    if (J_pose) {
      // d p_c / d(rho, phi) = [I, -[p_c]x] for T <- exp(delta) T.
      J_pose->leftCols<3>() = J_proj;
      J_pose->rightCols<3>() = -J_proj * skew(p_c);
    }
    if (J_point) *J_point = J_proj * R_cw;
    return true;
  }
};

}  // namespace lvslam::visual
