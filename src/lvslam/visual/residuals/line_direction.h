#pragma once
// Line direction residual (Cao et al., eq. e_dir):
//   e_dir = 1 - cos(d_cam, d_fu),
// the angle between a line landmark's direction d_cam and the direction d_fu
// the fusion framework reconstructed for it. Used under a robust loss and
// without an information matrix (the angle does not depend on the pyramid level).
//
// Sign convention: a line's direction has no orientation ((m, d) and (-m, -d)
// are the same line), so the residual uses |cos|: parallel and anti-parallel
// directions both give 0, perpendicular ones give 1. The Jacobian takes the
// sign of cos; at exactly 90 degrees it picks +.
#include <cmath>

#include <ceres/sized_cost_function.h>

#include <Eigen/Core>

#include "lvslam/visual/residuals/pose_block.h"

namespace lvslam::visual {

struct LineDirection {
  // d: the landmark's (unnormalised) direction; fusion_unit: unit d_fu.
  static bool evaluate(const Eigen::Vector3d& d, const Eigen::Vector3d& fusion_unit, double weight,
                       double& residual, Eigen::Matrix<double, 1, 3>* J_d) {
    const double dn = d.norm();
    if (!(dn > 1e-12) || !d.allFinite()) return false;
    const double cos_angle = d.dot(fusion_unit) / dn;
    const double sign = cos_angle < 0.0 ? -1.0 : 1.0;
    residual = weight * (1.0 - sign * cos_angle);
    if (J_d) {
      // d cos / d d = (f - cos d / |d|) / |d|.
      *J_d = -weight * sign * (fusion_unit - cos_angle * d / dn).transpose() / dn;
    }
    return true;
  }
};

// Block: line (m, d) (OrthonormalLineManifold); only d enters.
class LineDirectionCost final : public ceres::SizedCostFunction<1, kLineBlockSize> {
 public:
  // fusion_direction need not be unit; it must not be zero.
  LineDirectionCost(const Eigen::Vector3d& fusion_direction, double weight)
      : fusion_unit_(fusion_direction.normalized()), weight_(weight) {}

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const Eigen::Vector3d d = Eigen::Map<const Eigen::Vector3d>(parameters[0] + 3);
    Eigen::Matrix<double, 1, 3> J_d;
    const bool want = jacobians && jacobians[0];
    if (!LineDirection::evaluate(d, fusion_unit_, weight_, residuals[0], want ? &J_d : nullptr)) {
      return false;
    }
    if (want) {
      Eigen::Map<Eigen::Matrix<double, 1, 6>> J(jacobians[0]);
      J.leftCols<3>().setZero();
      J.rightCols<3>() = J_d;
    }
    return true;
  }

 private:
  Eigen::Vector3d fusion_unit_;
  double weight_;
};

}  // namespace lvslam::visual
