#include "lvslam/core/se3.h"

#include <algorithm>
#include <cmath>

namespace lvslam {

namespace {
constexpr double kSmallAngle = 1e-8;
}

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d S;
  S << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return S;
}

Eigen::Matrix3d expSO3(const Eigen::Vector3d& phi) {
  const double theta = phi.norm();
  if (theta < kSmallAngle) return Eigen::Matrix3d::Identity() + skew(phi);
  return Eigen::AngleAxisd(theta, phi / theta).toRotationMatrix();
}

Eigen::Vector3d logSO3(const Eigen::Matrix3d& R) {
  // Through the quaternion: well conditioned for every angle up to pi.
  Eigen::Quaterniond q(R);
  q.normalize();
  if (q.w() < 0.0) q.coeffs() *= -1.0;
  const Eigen::Vector3d v = q.vec();
  const double sin_half = v.norm();
  if (sin_half < kSmallAngle) return 2.0 * v;
  const double theta = 2.0 * std::atan2(sin_half, q.w());
  return theta * v / sin_half;
}

Eigen::Matrix3d leftJacobianSO3(const Eigen::Vector3d& phi) {
  const double theta = phi.norm();
  const Eigen::Matrix3d W = skew(phi);
  if (theta < 1e-5) return Eigen::Matrix3d::Identity() + 0.5 * W + W * W / 6.0;
  const double t2 = theta * theta;
  return Eigen::Matrix3d::Identity() + (1.0 - std::cos(theta)) / t2 * W +
         (theta - std::sin(theta)) / (t2 * theta) * W * W;
}

Eigen::Matrix3d leftJacobianSO3Inverse(const Eigen::Vector3d& phi) {
  const double theta = phi.norm();
  const Eigen::Matrix3d W = skew(phi);
  if (theta < 1e-5) return Eigen::Matrix3d::Identity() - 0.5 * W + W * W / 12.0;
  const double half = 0.5 * theta;
  const double cot_half = std::cos(half) / std::sin(half);
  return Eigen::Matrix3d::Identity() - 0.5 * W +
         (1.0 - half * cot_half) / (theta * theta) * W * W;
}

Eigen::Isometry3d expSE3(const Vector6d& xi) {
  const Eigen::Vector3d rho = xi.head<3>();
  const Eigen::Vector3d phi = xi.tail<3>();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = expSO3(phi);
  T.translation() = leftJacobianSO3(phi) * rho;
  return T;
}

Vector6d logSE3(const Eigen::Isometry3d& T) {
  const Eigen::Vector3d phi = logSO3(T.linear());
  Vector6d xi;
  xi.head<3>() = leftJacobianSO3Inverse(phi) * T.translation();
  xi.tail<3>() = phi;
  return xi;
}

bool isRotation(const Eigen::Matrix3d& R, double tol) {
  if (!R.allFinite()) return false;
  const double orth = (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  return orth <= tol && std::abs(R.determinant() - 1.0) <= tol;
}

bool isRigidTransform(const Eigen::Isometry3d& T, double tol) {
  return T.matrix().allFinite() && isRotation(T.linear(), tol);
}

Eigen::Matrix3d closestRotation(const Eigen::Matrix3d& M) {
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
  D(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  return svd.matrixU() * D * svd.matrixV().transpose();
}

Eigen::Isometry3d makePose(const Eigen::Quaterniond& q, const Eigen::Vector3d& t) {
  return makePose(q.normalized().toRotationMatrix(), t);
}

Eigen::Isometry3d makePose(const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = R;
  T.translation() = t;
  return T;
}

Eigen::Isometry3d interpolate(const Eigen::Isometry3d& T_a, const Eigen::Isometry3d& T_b, double s) {
  const Eigen::Quaterniond q_a(T_a.linear());
  const Eigen::Quaterniond q_b(T_b.linear());
  const Eigen::Vector3d t = (1.0 - s) * T_a.translation() + s * T_b.translation();
  // Eigen's slerp takes the short arc and handles nearly equal rotations.
  return makePose(q_a.slerp(s, q_b), t);
}

Eigen::Isometry3d interpolateAtTime(double t, double t0, const Eigen::Isometry3d& T0, double t1,
                                    const Eigen::Isometry3d& T1) {
  if (t1 == t0) return T0;
  const double s = (t - t0) / (t1 - t0);
  if (s >= 0.0 && s <= 1.0) return interpolate(T0, T1, s);
  // Outside the interval slerp does not extrapolate: use the constant twist.
  const Vector6d xi = logSE3(T0.inverse() * T1);
  const Eigen::Vector3d w = xi.tail<3>();
  Eigen::Isometry3d delta = Eigen::Isometry3d::Identity();
  delta.linear() = expSO3(s * w);
  delta.translation() = s * (T0.linear().transpose() * (T1.translation() - T0.translation()));
  return T0 * delta;
}

double rotationAngle(const Eigen::Isometry3d& T) {
  const double c = std::clamp((T.linear().trace() - 1.0) * 0.5, -1.0, 1.0);
  // acos loses precision near 0; use the log when the angle is small.
  if (c > 0.999) return logSO3(T.linear()).norm();
  return std::acos(c);
}

Eigen::Isometry3d leftUpdate(const Vector6d& delta, const Eigen::Isometry3d& T) {
  Eigen::Isometry3d out = expSE3(delta) * T;
  out.linear() = Eigen::Quaterniond(out.linear()).normalized().toRotationMatrix();
  return out;
}

Eigen::Isometry3d boundedStep(const Eigen::Isometry3d& T_from, const Eigen::Isometry3d& T_to, double max_m,
                              double max_rad) {
  const Vector6d xi = logSE3(T_from.inverse() * T_to);
  const double distance = xi.head<3>().norm(), angle = xi.tail<3>().norm();
  double s = 1.0;
  if (distance > max_m) s = std::min(s, max_m / distance);
  if (angle > max_rad) s = std::min(s, max_rad / angle);
  return s >= 1.0 ? T_to : T_from * expSE3(s * xi);
}

}  // namespace lvslam
