#include "lvslam/visual/geometry/orthonormal_line.h"

#include <cmath>

#include <Eigen/Geometry>

#include "lvslam/core/se3.h"

namespace lvslam::visual {

OrthonormalLine OrthonormalLine::fromPlucker(const PluckerLine& line) {
  OrthonormalLine o;
  const double mn = line.m.norm(), dn = line.d.norm();
  const Eigen::Vector3d u2 = line.d / dn;
  Eigen::Vector3d u1;
  if (mn > 1e-12 * dn) {
    u1 = line.m / mn;
  } else {
    // A line through the origin has m = 0: any unit vector normal to d serves
    // (w1 = 0 makes the choice irrelevant to the line).
    u1 = u2.unitOrthogonal();
  }
  o.U.col(0) = u1;
  o.U.col(1) = u2;
  o.U.col(2) = u1.cross(u2);
  o.w = Eigen::Vector2d(mn, dn) / std::hypot(mn, dn);
  return o;
}

PluckerLine OrthonormalLine::toPlucker() const {
  return PluckerLine{w.x() * U.col(0), w.y() * U.col(1)};
}

OrthonormalLine OrthonormalLine::plus(const Eigen::Vector4d& delta) const {
  OrthonormalLine o;
  o.U = U * expSO3(delta.head<3>());
  const double c = std::cos(delta[3]), s = std::sin(delta[3]);
  // W R(phi): first column rotates by phi.
  o.w = Eigen::Vector2d(c * w.x() - s * w.y(), s * w.x() + c * w.y());
  return o;
}

Eigen::Vector4d OrthonormalLine::minus(const OrthonormalLine& other) const {
  Eigen::Vector4d delta;
  delta.head<3>() = logSO3(U.transpose() * other.U);
  // Angle of W^T W_other.
  delta[3] = std::atan2(w.x() * other.w.y() - w.y() * other.w.x(),
                        w.x() * other.w.x() + w.y() * other.w.y());
  return delta;
}

Eigen::Matrix<double, 6, 4> orthonormalPlusJacobian(const OrthonormalLine& line) {
  // d u1 = theta3 u2 - theta2 u3, d u2 = theta1 u3 - theta3 u1 (from U [theta]x),
  // d w1 = -w2 phi, d w2 = w1 phi (PL-VINS / Structure PLP).
  const Eigen::Vector3d u1 = line.U.col(0), u2 = line.U.col(1), u3 = line.U.col(2);
  const double w1 = line.w.x(), w2 = line.w.y();
  Eigen::Matrix<double, 6, 4> J = Eigen::Matrix<double, 6, 4>::Zero();
  J.block<3, 1>(0, 1) = -w1 * u3;
  J.block<3, 1>(0, 2) = w1 * u2;
  J.block<3, 1>(0, 3) = -w2 * u1;
  J.block<3, 1>(3, 0) = w2 * u3;
  J.block<3, 1>(3, 2) = -w2 * u1;
  J.block<3, 1>(3, 3) = w1 * u2;
  return J;
}

}  // namespace lvslam::visual
