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

}  // namespace lvslam::visual
