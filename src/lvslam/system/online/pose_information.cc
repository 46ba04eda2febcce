#include "lvslam/system/online/pose_information.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

namespace lvslam::system {

Matrix6d adjointSE3(const Eigen::Isometry3d& T) {
  const Eigen::Matrix3d R = T.linear();
  Matrix6d Ad = Matrix6d::Zero();
  Ad.topLeftCorner<3, 3>() = R;
  Ad.topRightCorner<3, 3>() = skew(T.translation()) * R;
  Ad.bottomRightCorner<3, 3>() = R;
  return Ad;
}

Matrix6d lidarToCameraInformation(const Matrix6d& information_lidar, const Eigen::Isometry3d& T_camera_lidar) {
  // Omega_camera = Ad^-T Omega_lidar Ad^-1, and Ad(T)^-1 = Ad(T^-1).
  const Matrix6d Ad_inverse = adjointSE3(T_camera_lidar.inverse());
  return Ad_inverse.transpose() * information_lidar * Ad_inverse;
}

PseudoInverse pseudoInverse(const Matrix6d& symmetric, double relative_tolerance) {
  PseudoInverse result;
  const Eigen::SelfAdjointEigenSolver<Matrix6d> solver(0.5 * (symmetric + symmetric.transpose()));
  const double largest = solver.eigenvalues()(5);
  if (!(largest > 0.0) || !std::isfinite(largest)) {
    result.range.resize(6, 0);
    return result;
  }
  result.range.resize(6, 6);
  for (int i = 0; i < 6; ++i) {
    const double lambda = solver.eigenvalues()(i);
    if (lambda <= relative_tolerance * largest) continue;
    const Vector6d v = solver.eigenvectors().col(i);
    result.inverse += v * v.transpose() / lambda;
    result.range.col(result.rank++) = v;
  }
  result.range.conservativeResize(6, result.rank);
  return result;
}

Matrix6d informationOn(const Eigen::Matrix<double, 6, Eigen::Dynamic>& range, const Matrix6d& covariance) {
  if (range.cols() == 0) return Matrix6d::Zero();
  const Eigen::MatrixXd reduced = range.transpose() * covariance * range;
  return range * reduced.inverse() * range.transpose();
}

Matrix6d isotropicCovariance(double sigma_m, double sigma_rad) {
  Vector6d diagonal;
  diagonal << Eigen::Vector3d::Constant(sigma_m * sigma_m), Eigen::Vector3d::Constant(sigma_rad * sigma_rad);
  return diagonal.asDiagonal();
}

double chiSquare999(int dof) {
  static constexpr double kQuantiles[] = {10.828, 13.816, 16.266, 18.467, 20.515, 22.458};
  return kQuantiles[std::clamp(dof, 1, 6) - 1];
}

Vector6d poseDifference(const Eigen::Isometry3d& T_a, const Eigen::Isometry3d& T_b) {
  const Eigen::Isometry3d T_ab = T_a.inverse() * T_b;
  Vector6d xi;
  xi << T_ab.translation(), logSO3(T_ab.linear());
  return xi;
}

}  // namespace lvslam::system
