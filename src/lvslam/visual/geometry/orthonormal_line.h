#pragma once
// The minimal 4-DoF orthonormal representation of a 3D line (Bartoli & Sturm
// 2005, as used by PL-VINS and Structure PLP-SLAM): a Plücker line (m, d) as
// U = [m/|m|, d/|d|, (m x d)/|m x d|] in SO(3) and W = [w1 -w2; w2 w1] in
// SO(2), (w1, w2) = (|m|, |d|) / |(m, d)|. Updates are U Exp(theta),
// W R(phi) for (theta, phi) in R^4.
#include <Eigen/Core>

#include "lvslam/core/plucker_line.h"

namespace lvslam::visual {

struct OrthonormalLine {
  Eigen::Matrix3d U = Eigen::Matrix3d::Identity();
  Eigen::Vector2d w = Eigen::Vector2d(1.0, 0.0);  // (cos, sin) of W's angle

  static OrthonormalLine fromPlucker(const PluckerLine& line);
  // The Plücker line (w1 u1, w2 u2), scaled so |(m, d)| = 1.
  PluckerLine toPlucker() const;

  // Retraction with delta = (theta (3), phi (1)).
  OrthonormalLine plus(const Eigen::Vector4d& delta) const;
  // The delta with other = this->plus(delta) (for small differences).
  Eigen::Vector4d minus(const OrthonormalLine& other) const;
};

// d(m, d)/d(delta) of toPlucker(plus(delta)) at delta = 0 (6x4).
Eigen::Matrix<double, 6, 4> orthonormalPlusJacobian(const OrthonormalLine& line);

}  // namespace lvslam::visual
