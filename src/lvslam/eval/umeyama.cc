#include "lvslam/eval/umeyama.h"

#include <limits>

#include <Eigen/LU>
#include <Eigen/SVD>
#include <fmt/format.h>

#include "lvslam/core/error.h"

namespace lvslam::eval {

Similarity3 umeyamaAlignment(const Eigen::Matrix3Xd& from, const Eigen::Matrix3Xd& to,
                             bool with_scale) {
  if (from.cols() != to.cols() || from.cols() == 0)
    throw Error("Umeyama alignment",
                fmt::format("needs two equal, non-empty point sets ({} and {} points)", from.cols(),
                            to.cols()));
  const double n = static_cast<double>(from.cols());
  // Means and variance of the source, Umeyama eqs. (34)-(36).
  const Eigen::Vector3d mean_from = from.rowwise().mean();
  const Eigen::Vector3d mean_to = to.rowwise().mean();
  const Eigen::Matrix3Xd centred_from = from.colwise() - mean_from;
  const Eigen::Matrix3Xd centred_to = to.colwise() - mean_to;
  const double variance_from = centred_from.squaredNorm() / n;
  // Cross covariance, eq. (38).
  const Eigen::Matrix3d covariance = centred_to * centred_from.transpose() / n;

  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Vector3d d = svd.singularValues();
  // evo's test: fewer than m-1 singular values above machine epsilon.
  const int rank = static_cast<int>((d.array() > std::numeric_limits<double>::epsilon()).count());
  if (rank < 2)
    throw Error("Umeyama alignment",
                "degenerate positions (all equal, or all on one line): the rotation is undetermined");

  // S of eq. (43): flips the last axis when U V^T would be a reflection.
  Eigen::Vector3d s = Eigen::Vector3d::Ones();
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0.0) s(2) = -1.0;

  Similarity3 result;
  result.R = svd.matrixU() * s.asDiagonal() * svd.matrixV().transpose();  // eq. (40)
  result.scale = with_scale ? d.dot(s) / variance_from : 1.0;            // eq. (42)
  result.t = mean_to - result.scale * (result.R * mean_from);            // eq. (41)
  return result;
}

}  // namespace lvslam::eval
