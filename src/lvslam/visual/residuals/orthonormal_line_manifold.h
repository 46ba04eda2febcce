#pragma once
// Ceres manifold of a line block (unit-norm Plücker (m, d)) with the 4-DoF
// orthonormal update U Exp(theta), W R(phi) (Bartoli & Sturm; PL-VINS,
// Structure PLP). Unlike the pose manifold, PlusJacobian is the true 6x4
// derivative, so cost functions give d(residual)/d(m, d).
#include <ceres/manifold.h>

#include <Eigen/Dense>

#include "lvslam/visual/geometry/orthonormal_line.h"
#include "lvslam/visual/residuals/pose_block.h"

namespace lvslam::visual {

class OrthonormalLineManifold final : public ceres::Manifold {
 public:
  int AmbientSize() const override { return kLineBlockSize; }
  int TangentSize() const override { return kLineTangentSize; }

  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override {
    const OrthonormalLine o = orthonormal(x).plus(Eigen::Map<const Eigen::Vector4d>(delta));
    Eigen::Map<Vector6d>{x_plus_delta} = o.toPlucker().vector();
    return true;
  }
  bool PlusJacobian(const double* x, double* jacobian) const override {
    Eigen::Map<Eigen::Matrix<double, 6, 4, Eigen::RowMajor>>{jacobian} =
        orthonormalPlusJacobian(orthonormal(x));
    return true;
  }
  bool Minus(const double* y, const double* x, double* y_minus_x) const override {
    Eigen::Map<Eigen::Vector4d>{y_minus_x} = orthonormal(x).minus(orthonormal(y));
    return true;
  }
  bool MinusJacobian(const double* x, double* jacobian) const override {
    const Eigen::Matrix<double, 6, 4> J = orthonormalPlusJacobian(orthonormal(x));
    Eigen::Map<Eigen::Matrix<double, 4, 6, Eigen::RowMajor>>{jacobian} =
        J.completeOrthogonalDecomposition().pseudoInverse();
    return true;
  }

 private:
  static OrthonormalLine orthonormal(const double* x) {
    return OrthonormalLine::fromPlucker(PluckerLine::fromVector(Eigen::Map<const Vector6d>(x)));
  }
};

}  // namespace lvslam::visual
