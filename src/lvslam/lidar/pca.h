#pragma once
// Shape of a local neighbourhood by PCA (Hackel et al. 2016; Weinmann et al.
// 2013), the descriptors MULLS and the paper classify with.
#include <Eigen/Core>

namespace lvslam::lidar {

struct LocalShape {
  Eigen::Vector3f line_direction = Eigen::Vector3f::UnitX();  // e1, largest eigenvalue
  Eigen::Vector3f normal = Eigen::Vector3f::UnitZ();          // e3, smallest eigenvalue
  float linearity = 0.0f;   // (l1 - l2) / l1
  float planarity = 0.0f;   // (l2 - l3) / l1
  float curvature = 0.0f;   // l3 / (l1 + l2 + l3)
  bool valid = false;       // false when the neighbourhood has no spread
};

// Eigen-decomposition of the covariance of the given positions.
template <typename PositionRange>
LocalShape shapeOf(const PositionRange& positions);

// From a covariance (any scale) to the descriptors.
LocalShape shapeFromCovariance(const Eigen::Matrix3d& covariance);

template <typename PositionRange>
LocalShape shapeOf(const PositionRange& positions) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  int n = 0;
  for (const auto& p : positions) {
    mean += p.template cast<double>();
    ++n;
  }
  if (n < 3) return {};
  mean /= n;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& p : positions) {
    const Eigen::Vector3d d = p.template cast<double>() - mean;
    cov += d * d.transpose();
  }
  return shapeFromCovariance(cov / n);
}

}  // namespace lvslam::lidar
