#pragma once
// Line endpoint reprojection residual (Cao et al., eq. e_dis):
//   e_dis = [x_s^T l' / sqrt(l1^2 + l2^2), x_e^T l' / sqrt(l1^2 + l2^2)]^T,
// l' = K_line m_c the projected world line, x_s, x_e the observed endpoints.
// Analytic Jacobians for the left SE3 pose update and the Plücker line.

#include <Eigen/Core>

#include "lvslam/core/se3.h"
#include "lvslam/visual/residuals/pose_block.h"

namespace lvslam::visual {

struct LineReprojection {
  // False when the line passes (nearly) through the camera centre.
  static bool evaluate(const Eigen::Matrix3d& R_cw, const Eigen::Vector3d& t_cw,
                       const Vector6d& L_w, const Eigen::Vector3d& start_h,
                       const Eigen::Vector3d& end_h, const Eigen::Matrix3d& K_line, double sqrt_info,
                       Eigen::Vector2d& residual, Eigen::Matrix<double, 2, 6>* J_pose,
                       Eigen::Matrix<double, 2, 6>* J_line) {
    const Eigen::Vector3d d_c = R_cw * L_w.tail<3>();
    const Eigen::Vector3d m_c = R_cw * L_w.head<3>() + t_cw.cross(d_c);
    const Eigen::Vector3d l = K_line * m_c;
    const double n2 = l.head<2>().squaredNorm();
    if (!(n2 > 1e-18) || !l.allFinite()) return false;
    const double inv_n = 1.0 / std::sqrt(n2);
    const double ds = start_h.dot(l), de = end_h.dot(l);
    residual = sqrt_info * inv_n * Eigen::Vector2d(ds, de);
    if (!J_pose && !J_line) return true;
    // d e_i / d l = x_i^T / n - (x_i . l) [l1, l2, 0] / n^3.
    const Eigen::Vector3d l12(l.x(), l.y(), 0.0);
    const double inv_n3 = inv_n * inv_n * inv_n;
    Eigen::Matrix<double, 2, 3> J_l;
    J_l.row(0) = start_h.transpose() * inv_n - ds * inv_n3 * l12.transpose();
    J_l.row(1) = end_h.transpose() * inv_n - de * inv_n3 * l12.transpose();
    const Eigen::Matrix<double, 2, 3> J_m = sqrt_info * J_l * K_line;
    if (J_pose) {
      // d m_c / d(rho, phi) = [-[d_c]x, -[m_c]x] for T <- exp(delta) T.
      J_pose->leftCols<3>() = -J_m * skew(d_c);
      J_pose->rightCols<3>() = -J_m * skew(m_c);
    }
    if (J_line) {
      // m_c = [R, [t]x R] (m_w, d_w).
      J_line->leftCols<3>() = J_m * R_cw;
      J_line->rightCols<3>() = J_m * skew(t_cw) * R_cw;
    }
    return true;
  }
};

}  // namespace lvslam::visual
