#include "lvslam/core/plucker_line.h"

#include <cmath>

#include "lvslam/core/se3.h"

namespace lvslam {

PluckerLine PluckerLine::fromPoints(const Eigen::Vector3d& A, const Eigen::Vector3d& B) {
  return PluckerLine{A.cross(B), B - A};
}

PluckerLine PluckerLine::fromVector(const Vector6d& v) {
  return PluckerLine{v.head<3>(), v.tail<3>()};
}

Vector6d PluckerLine::vector() const {
  Vector6d v;
  v << m, d;
  return v;
}

PluckerLine PluckerLine::normalized() const {
  const double n = d.norm();
  return PluckerLine{m / n, d / n};
}

PluckerLine PluckerLine::transformed(const Eigen::Isometry3d& T_a_b) const {
  const Eigen::Matrix3d R = T_a_b.linear();
  const Eigen::Vector3d d_a = R * d;
  return PluckerLine{R * m + T_a_b.translation().cross(d_a), d_a};
}

Eigen::Vector3d PluckerLine::closestPointToOrigin() const { return d.cross(m) / d.squaredNorm(); }

Eigen::Vector3d PluckerLine::closestPointTo(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d p0 = closestPointToOrigin();
  return p0 + d * (d.dot(p - p0) / d.squaredNorm());
}

double PluckerLine::distanceTo(const Eigen::Vector3d& p) const {
  // |p x d - m| / |d|: the moment about p vanishes only on the line.
  return (p.cross(d) - m).norm() / d.norm();
}

bool PluckerLine::closestPointToRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                    Eigen::Vector3d& point_on_line) const {
  // Common perpendicular of two lines: solve for the parameter on this line.
  const Eigen::Vector3d p0 = closestPointToOrigin();
  const Eigen::Vector3d u = d.normalized();
  const Eigen::Vector3d v = direction.normalized();
  const double b = u.dot(v);
  const double denom = 1.0 - b * b;
  if (denom < 1e-12) return false;
  const Eigen::Vector3d w = p0 - origin;
  const double s = (b * v.dot(w) - u.dot(w)) / denom;
  point_on_line = p0 + s * u;
  return true;
}

bool PluckerLine::isValid(double tol) const {
  const double dn = d.norm();
  if (!(dn > tol) || !m.allFinite() || !d.allFinite()) return false;
  return std::abs(m.dot(d)) <= tol * std::max(1.0, m.norm() * dn);
}

Eigen::Matrix<double, 6, 6> pluckerTransformMatrix(const Eigen::Isometry3d& T_a_b) {
  const Eigen::Matrix3d R = T_a_b.linear();
  Eigen::Matrix<double, 6, 6> M = Eigen::Matrix<double, 6, 6>::Zero();
  M.topLeftCorner<3, 3>() = R;
  M.topRightCorner<3, 3>() = skew(T_a_b.translation()) * R;
  M.bottomRightCorner<3, 3>() = R;
  return M;
}

}  // namespace lvslam
