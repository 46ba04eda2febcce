#include "lvslam/system/pose_fusion.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

namespace lvslam::system {

Matrix6d isotropicPoseInformation(double sigma_m, double sigma_rad) {
  Matrix6d H = Matrix6d::Zero();
  H.topLeftCorner<3, 3>().diagonal().setConstant(1.0 / (sigma_m * sigma_m));
  H.bottomRightCorner<3, 3>().diagonal().setConstant(1.0 / (sigma_rad * sigma_rad));
  return H;
}

Matrix6d lidarPoseInformation(const PoseFusionConfig& c, double path_m) {
  const double s = std::max(path_m, 0.0);
  const double deg = M_PI / 180.0;
  const double sigma_m = std::sqrt(c.lidar_sigma_m * c.lidar_sigma_m + c.lidar_drift_m * c.lidar_drift_m * s);
  const double sigma_deg = std::sqrt(c.lidar_sigma_deg * c.lidar_sigma_deg + c.lidar_drift_deg * c.lidar_drift_deg * s);
  return isotropicPoseInformation(sigma_m, sigma_deg * deg);
}

Matrix6d decoupledInformation(const Matrix6d& information) {
  // Marginals in information form (Schur complements), which stay defined
  // when a direction is unknown (zero information): H_tt - H_tr H_rr^-1 H_rt
  // and H_rr - H_rt H_tt^-1 H_tr (LDLT solves semi-definite blocks as
  // pseudo-inverses).
  const Eigen::Matrix3d H_tt = information.topLeftCorner<3, 3>();
  const Eigen::Matrix3d H_rr = information.bottomRightCorner<3, 3>();
  const Eigen::Matrix3d H_tr = information.topRightCorner<3, 3>();
  const Eigen::Matrix3d translation = H_tt - H_tr * Eigen::LDLT<Eigen::Matrix3d>(H_rr).solve(H_tr.transpose());
  const Eigen::Matrix3d rotation = H_rr - H_tr.transpose() * Eigen::LDLT<Eigen::Matrix3d>(H_tt).solve(H_tr);
  Matrix6d out = Matrix6d::Zero();
  out.topLeftCorner<3, 3>() = 0.5 * (translation + translation.transpose());
  out.bottomRightCorner<3, 3>() = 0.5 * (rotation + rotation.transpose());
  return out.allFinite() ? out : Matrix6d::Zero();
}

Eigen::Isometry3d fusePoses(const Eigen::Isometry3d& T_camera_world_a, const Matrix6d& information_a,
                            const Eigen::Isometry3d& T_camera_world_b, const Matrix6d& information_b) {
  const Vector6d delta_b = logSE3(T_camera_world_b * T_camera_world_a.inverse());
  const Eigen::LDLT<Matrix6d> sum(information_a + information_b);
  if (sum.info() != Eigen::Success || !sum.isPositive()) return T_camera_world_a;
  const Vector6d delta = sum.solve(information_b * delta_b);
  if (!delta.allFinite()) return T_camera_world_a;
  return leftUpdate(delta, T_camera_world_a);
}

}  // namespace lvslam::system
