#pragma once
// Ceres manifold of a pose block [t, q] with the left SE3 update
// T <- expSE3(delta) T, delta = (rho, phi).
//
// Convention (as VINS-Mono and others): the analytic cost functions of this
// folder write d(residual)/d(delta) into the first 6 columns of their 7-column
// pose Jacobian and zero into the last; PlusJacobian is therefore [I6; 0], so
// Ceres' product J * PlusJacobian is exactly the tangent Jacobian without a
// 7x6 multiply. Only cost functions that follow this convention may be used
// on a block with this manifold.
#include <ceres/manifold.h>

#include "lvslam/core/se3.h"
#include "lvslam/visual/residuals/pose_block.h"

namespace lvslam::visual {

class Se3LeftManifold final : public ceres::Manifold {
 public:
  int AmbientSize() const override { return kPoseBlockSize; }
  int TangentSize() const override { return kPoseTangentSize; }

  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override {
    const Vector6d d = Eigen::Map<const Vector6d>(delta);
    const PoseBlock out = toPoseBlock(expSE3(d) * fromPoseBlock(x));
    std::copy(out.begin(), out.end(), x_plus_delta);
    return true;
  }
  bool PlusJacobian(const double*, double* jacobian) const override {
    Eigen::Map<Eigen::Matrix<double, 7, 6, Eigen::RowMajor>> J(jacobian);
    J.setZero();
    J.topRows<6>().setIdentity();
    return true;
  }
  bool Minus(const double* y, const double* x, double* y_minus_x) const override {
    Eigen::Map<Vector6d>{y_minus_x} = logSE3(fromPoseBlock(y) * fromPoseBlock(x).inverse());
    return true;
  }
  bool MinusJacobian(const double*, double* jacobian) const override {
    Eigen::Map<Eigen::Matrix<double, 6, 7, Eigen::RowMajor>> J(jacobian);
    J.setZero();
    J.leftCols<6>().setIdentity();
    return true;
  }
};

}  // namespace lvslam::visual
