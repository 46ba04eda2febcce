#include "lvslam/system/online/relative_pose_cost.h"

#include "lvslam/core/relative_pose_error.h"

namespace lvslam::system {

namespace {

using RowMajor67 = Eigen::Matrix<double, 6, 7, Eigen::RowMajor>;

// d q / d delta of Ceres' EigenQuaternionManifold, q <- [cos|d|, sin|d| d/|d|] q,
// rows (x, y, z, w). Its columns are orthonormal at a unit q, so its
// transpose takes a tangent Jacobian to an ambient one that the manifold
// maps back exactly.
Eigen::Matrix<double, 4, 3> quaternionPlusJacobian(const Eigen::Quaterniond& q) {
  Eigen::Matrix<double, 4, 3> P;
  P.topRows<3>() = q.w() * Eigen::Matrix3d::Identity() - skew(q.vec());
  P.row(3) = -q.vec().transpose();
  return P;
}

// From the tangent Jacobian (translation, then the rotation vector phi of
// a world-frame left update R <- exp(phi) R) to the 7 ambient columns.
RowMajor67 ambient(const Matrix6d& J_tangent, const Eigen::Quaterniond& q) {
  RowMajor67 J;
  J.leftCols<3>() = J_tangent.leftCols<3>();
  // Ceres' delta is half the rotation vector: d/d delta = 2 d/d phi.
  J.rightCols<4>() = 2.0 * J_tangent.rightCols<3>() * quaternionPlusJacobian(q).transpose();
  return J;
}

}  // namespace

RelativePoseCost::RelativePoseCost(const Eigen::Isometry3d& T_from_to, const Matrix6d& sqrt_information)
    : t_z_(T_from_to.translation()), q_z_(T_from_to.linear()), sqrt_information_(sqrt_information) {}

bool RelativePoseCost::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
  const Eigen::Map<const Eigen::Vector3d> t_a(parameters[0]), t_b(parameters[1]);
  const Eigen::Map<const Eigen::Quaterniond> q_a(parameters[0] + 3), q_b(parameters[1] + 3);
  const Vector6d e = relativePoseError<double>(t_a, q_a, t_b, q_b, t_z_, q_z_);
  Eigen::Map<Vector6d> r(residuals);
  r = sqrt_information_ * e;
  if (!jacobians || (!jacobians[0] && !jacobians[1])) return true;

  // Right-perturbation error of Z^-1 T_a^-1 T_b under left updates of a and b.
  const Eigen::Matrix3d M = (q_z_.conjugate() * q_a.conjugate()).toRotationMatrix();  // R_z^T R_a^T
  Eigen::Quaterniond q_error = q_z_.conjugate() * (q_a.conjugate() * q_b);
  if (q_error.w() < 0.0) q_error.coeffs() = -q_error.coeffs();  // as the residual does
  // 2 vec((1, M phi / 2) q_error) moves by (w I - [v]x) M phi.
  const Eigen::Matrix3d D = (q_error.w() * Eigen::Matrix3d::Identity() - skew(q_error.vec())) * M;
  if (jacobians[0]) {
    Matrix6d J = Matrix6d::Zero();
    J.block<3, 3>(0, 0) = -M;
    J.block<3, 3>(0, 3) = M * skew(t_b - t_a);
    J.block<3, 3>(3, 3) = -D;
    Eigen::Map<RowMajor67> J_a(jacobians[0]);
    J_a = sqrt_information_ * ambient(J, q_a);
  }
  if (jacobians[1]) {
    Matrix6d J = Matrix6d::Zero();
    J.block<3, 3>(0, 0) = M;
    J.block<3, 3>(3, 3) = D;
    Eigen::Map<RowMajor67> J_b(jacobians[1]);
    J_b = sqrt_information_ * ambient(J, q_b);
  }
  return true;
}

}  // namespace lvslam::system
