#include "lvslam/lidar/pca.h"

#include <algorithm>

#include <Eigen/Eigenvalues>

namespace lvslam::lidar {

LocalShape shapeFromCovariance(const Eigen::Matrix3d& covariance) {
  LocalShape shape;
  if (!covariance.allFinite()) return shape;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(covariance);
  // Eigen sorts ascending: l3 <= l2 <= l1.
  const double l3 = std::max(solver.eigenvalues()(0), 0.0);
  const double l2 = std::max(solver.eigenvalues()(1), 0.0);
  const double l1 = std::max(solver.eigenvalues()(2), 0.0);
  if (!(l1 > 1e-12)) return shape;
  shape.linearity = static_cast<float>((l1 - l2) / l1);
  shape.planarity = static_cast<float>((l2 - l3) / l1);
  shape.curvature = static_cast<float>(l3 / (l1 + l2 + l3));
  shape.line_direction = solver.eigenvectors().col(2).normalized().cast<float>();
  shape.normal = solver.eigenvectors().col(0).normalized().cast<float>();
  shape.valid = shape.line_direction.allFinite() && shape.normal.allFinite();
  return shape;
}

}  // namespace lvslam::lidar
