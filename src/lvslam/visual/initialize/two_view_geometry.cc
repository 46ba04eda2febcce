#include "lvslam/visual/initialize/two_view_geometry.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <Eigen/SVD>

namespace lvslam::visual {

namespace {
constexpr double kChi2OneDof = 3.841;
constexpr double kChi2TwoDof = 5.991;
// Rays closer than this (about 0.36 deg, ORB-SLAM's 0.99998) give no depth.
constexpr double kMinTriangulationCos = 0.99998;

double transferError2(const Eigen::Matrix3d& H, const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  const Eigen::Vector3d p = H * from.homogeneous();
  if (!(std::abs(p.z()) > 1e-12)) return INFINITY;
  return (p.hnormalized() - to).squaredNorm();
}

double epipolarError2(const Eigen::Matrix3d& F, const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  const Eigen::Vector3d l = F * from.homogeneous();
  const double n2 = l.head<2>().squaredNorm();
  if (!(n2 > 1e-24)) return INFINITY;
  const double d = l.dot(to.homogeneous());
  return d * d / n2;
}

template <typename Forward, typename Backward>
double score(const Forward& forward, const Backward& backward, size_t n, double sigma, double gate,
             std::vector<bool>& inliers) {
  const double inv_s2 = 1.0 / (sigma * sigma);
  double total = 0.0;
  inliers.assign(n, false);
  for (size_t i = 0; i < n; ++i) {
    const double e12 = forward(i) * inv_s2, e21 = backward(i) * inv_s2;
    if (e12 < gate) total += kChi2TwoDof - e12;
    if (e21 < gate) total += kChi2TwoDof - e21;
    inliers[i] = e12 < gate && e21 < gate;
  }
  return total;
}
}  // namespace

Eigen::Vector3d triangulateDlt(const Eigen::Matrix<double, 3, 4>& P1, const Eigen::Matrix<double, 3, 4>& P2,
                               const Eigen::Vector2d& x1, const Eigen::Vector2d& x2) {
  Eigen::Matrix4d A;
  A.row(0) = x1.x() * P1.row(2) - P1.row(0);
  A.row(1) = x1.y() * P1.row(2) - P1.row(1);
  A.row(2) = x2.x() * P2.row(2) - P2.row(0);
  A.row(3) = x2.y() * P2.row(2) - P2.row(1);
  const Eigen::Vector4d X = Eigen::JacobiSVD<Eigen::Matrix4d>(A, Eigen::ComputeFullV).matrixV().col(3);
  return X.head<3>() / X.w();
}

double homographyScore(const Eigen::Matrix3d& H_21, const std::vector<Eigen::Vector2d>& x1,
                       const std::vector<Eigen::Vector2d>& x2, double sigma, std::vector<bool>& inliers) {
  const Eigen::Matrix3d H_12 = H_21.inverse();
  return score([&](size_t i) { return transferError2(H_21, x1[i], x2[i]); },
               [&](size_t i) { return transferError2(H_12, x2[i], x1[i]); }, x1.size(), sigma, kChi2TwoDof,
               inliers);
}

double fundamentalScore(const Eigen::Matrix3d& F_21, const std::vector<Eigen::Vector2d>& x1,
                        const std::vector<Eigen::Vector2d>& x2, double sigma, std::vector<bool>& inliers) {
  const Eigen::Matrix3d F_12 = F_21.transpose();
  return score([&](size_t i) { return epipolarError2(F_21, x1[i], x2[i]); },
               [&](size_t i) { return epipolarError2(F_12, x2[i], x1[i]); }, x1.size(), sigma, kChi2OneDof,
               inliers);
}

MotionHypothesisCheck checkMotionHypothesis(const Eigen::Matrix3d& R_21, const Eigen::Vector3d& t_21,
                                            const Eigen::Matrix3d& K, const std::vector<Eigen::Vector2d>& x1,
                                            const std::vector<Eigen::Vector2d>& x2,
                                            const std::vector<bool>& inliers, double sigma) {
  MotionHypothesisCheck out;
  out.points.assign(x1.size(), Eigen::Vector3d::Zero());
  out.triangulated.assign(x1.size(), false);
  Eigen::Matrix<double, 3, 4> P1 = Eigen::Matrix<double, 3, 4>::Zero(), P2;
  P1.leftCols<3>() = K;
  P2 << K * R_21, K * t_21;
  const Eigen::Vector3d centre2_in_1 = -R_21.transpose() * t_21;
  const double gate = 4.0 * sigma * sigma;  // ORB-SLAM's reprojection gate in checkRT
  std::vector<double> parallaxes;
  for (size_t i = 0; i < x1.size(); ++i) {
    if (!inliers[i]) continue;
    const Eigen::Vector3d X = triangulateDlt(P1, P2, x1[i], x2[i]);
    if (!X.allFinite()) continue;
    const Eigen::Vector3d X2 = R_21 * X + t_21;
    const double cos_parallax = X.normalized().dot((X - centre2_in_1).normalized());
    if (!(X.z() > 0.0) || !(X2.z() > 0.0)) continue;
    if ((((K * X).hnormalized()) - x1[i]).squaredNorm() > gate) continue;
    if ((((K * X2).hnormalized()) - x2[i]).squaredNorm() > gate) continue;
    ++out.num_good;
    parallaxes.push_back(std::acos(std::clamp(cos_parallax, -1.0, 1.0)) * 180.0 / M_PI);
    out.points[i] = X;
    out.triangulated[i] = cos_parallax < kMinTriangulationCos;
  }
  if (!parallaxes.empty()) {
    const auto mid = parallaxes.begin() + parallaxes.size() / 2;
    std::nth_element(parallaxes.begin(), mid, parallaxes.end());
    out.median_parallax_deg = *mid;
  }
  return out;
}

}  // namespace lvslam::visual
