#pragma once
// A 3D line in Plücker coordinates L = (m, d): direction d and moment
// m = p x d for any point p on the line (so m = A x B, d = B - A for two
// points A, B, the paper's eq. for fusion lines). (m, d) and (s m, s d),
// s != 0, describe the same line; m . d = 0 always holds.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace lvslam {

using Vector6d = Eigen::Matrix<double, 6, 1>;

struct PluckerLine {
  Eigen::Vector3d m = Eigen::Vector3d::Zero();  // moment
  Eigen::Vector3d d = Eigen::Vector3d::UnitX();  // direction (not necessarily unit)

  // Line through A and B: m = A x B, d = B - A (Cao et al., Sec. III-C).
  static PluckerLine fromPoints(const Eigen::Vector3d& A, const Eigen::Vector3d& B);
  // From the stacked vector (m^T, d^T)^T.
  static PluckerLine fromVector(const Vector6d& v);
  Vector6d vector() const;

  // Same line with |d| = 1.
  PluckerLine normalized() const;

  // Line in frame a from the line in frame b: d_a = R d_b, m_a = R m_b + t x (R d_b),
  // i.e. the 6x6 Plücker transform [R, [t]x R; 0, R].
  PluckerLine transformed(const Eigen::Isometry3d& T_a_b) const;

  // Point of the line closest to the origin: (d x m) / |d|^2.
  Eigen::Vector3d closestPointToOrigin() const;
  // Orthogonal projection of p onto the line.
  Eigen::Vector3d closestPointTo(const Eigen::Vector3d& p) const;
  double distanceTo(const Eigen::Vector3d& p) const;

  // Point of the line closest to the ray origin + s * direction, i.e. where
  // a back-projected pixel ray meets the line best (its endpoint along that ray).
  // Returns false when the ray is (nearly) parallel to the line.
  bool closestPointToRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                         Eigen::Vector3d& point_on_line) const;

  // True when d is not (nearly) zero and m . d is (nearly) zero.
  bool isValid(double tol = 1e-9) const;
};

// The 6x6 matrix that maps (m_b, d_b) to (m_a, d_a).
Eigen::Matrix<double, 6, 6> pluckerTransformMatrix(const Eigen::Isometry3d& T_a_b);

}  // namespace lvslam
