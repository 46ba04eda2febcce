#pragma once
// Least-squares similarity between two registered point sets (Umeyama 1991,
// "Least-squares estimation of transformation parameters between two point
// patterns", IEEE PAMI 13(4)), as evo's geometry.umeyama_alignment computes it.
#include <Eigen/Core>

namespace lvslam::eval {

// to ~= scale * R * from + t.
struct Similarity3 {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  double scale = 1.0;

  Eigen::Vector3d apply(const Eigen::Vector3d& p) const { return scale * (R * p) + t; }
};

// Points are the columns of `from` and `to` (same count, at least one).
// Scale stays 1 unless with_scale. Throws lvslam::Error when the cross
// covariance has rank below 2 (all points equal, or fewer than two distinct
// directions), where the rotation is not determined.
Similarity3 umeyamaAlignment(const Eigen::Matrix3Xd& from, const Eigen::Matrix3Xd& to,
                             bool with_scale);

}  // namespace lvslam::eval
