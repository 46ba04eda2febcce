#pragma once
// The error of a relative-pose measurement Z = T_a^-1 T_b between two poses
// given as translation and unit quaternion, (R_z^T (t_ab - t_z), 2 vec(q_z^-1 q_ab)):
// a right perturbation of b in the measurement's frame, ordered (rho, phi) as
// in Ceres' pose_graph_3d example. Templated for automatic differentiation.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace lvslam {

template <typename T>
Eigen::Matrix<T, 6, 1> relativePoseError(const Eigen::Matrix<T, 3, 1>& t_a, const Eigen::Quaternion<T>& q_a,
                                         const Eigen::Matrix<T, 3, 1>& t_b, const Eigen::Quaternion<T>& q_b,
                                         const Eigen::Vector3d& t_z, const Eigen::Quaterniond& q_z) {
  const Eigen::Quaternion<T> q_z_inverse = q_z.conjugate().cast<T>();
  const Eigen::Quaternion<T> q_a_inverse = q_a.conjugate();
  Eigen::Quaternion<T> q_error = q_z_inverse * (q_a_inverse * q_b);
  if (q_error.w() < T(0)) q_error.coeffs() = -q_error.coeffs();  // the shorter way round
  Eigen::Matrix<T, 6, 1> e;
  e.template head<3>() = q_z_inverse * (q_a_inverse * (t_b - t_a) - t_z.cast<T>());
  e.template tail<3>() = T(2) * q_error.vec();
  return e;
}

}  // namespace lvslam
