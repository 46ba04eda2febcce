#pragma once
// The pose graph's relative-pose factor as a Ceres cost with its Jacobians
// written out: the window is solved once or twice per camera frame, online
// and again in the offline replay, and automatic differentiation of this
// small residual was most of the solve's time.
#include <ceres/sized_cost_function.h>

#include <Eigen/Geometry>

#include "lvslam/core/se3.h"

namespace lvslam::system {

// Residual L (R_z^T (R_a^T (t_b - t_a) - t_z), 2 vec(q_z^-1 q_a^-1 q_b)) with
// L^T L the factor's information (relativePoseError, whitened). Parameter
// blocks [t (3), q (x, y, z, w)] with Ceres' EigenQuaternionManifold on q;
// the Jacobians are exact on the manifold's tangent (their component along
// the quaternion's norm is zero).
class RelativePoseCost : public ceres::SizedCostFunction<6, 7, 7> {
 public:
  RelativePoseCost(const Eigen::Isometry3d& T_from_to, const Matrix6d& sqrt_information);
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

 private:
  Eigen::Vector3d t_z_;
  Eigen::Quaterniond q_z_;
  Matrix6d sqrt_information_;
};

}  // namespace lvslam::system
