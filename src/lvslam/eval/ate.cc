#include "lvslam/eval/ate.h"

#include <cstddef>

#include <fmt/format.h>

#include "lvslam/core/error.h"

namespace lvslam::eval {

namespace {

Eigen::Matrix3Xd positionsOf(const std::vector<Eigen::Isometry3d>& poses) {
  Eigen::Matrix3Xd positions(3, static_cast<Eigen::Index>(poses.size()));
  for (std::size_t k = 0; k < poses.size(); ++k)
    positions.col(static_cast<Eigen::Index>(k)) = poses[k].translation();
  return positions;
}

}  // namespace

std::string alignmentName(Alignment alignment) {
  switch (alignment) {
    case Alignment::kNone: return "none";
    case Alignment::kSE3: return "se3";
    case Alignment::kSim3: return "sim3";
  }
  return "unknown";
}

AteResult computeAte(const std::vector<Eigen::Isometry3d>& gt,
                     const std::vector<Eigen::Isometry3d>& est, Alignment alignment) {
  if (gt.size() != est.size())
    throw Error("ATE", fmt::format("{} ground-truth poses but {} estimated poses", gt.size(),
                                   est.size()));
  const Eigen::Matrix3Xd p_gt = positionsOf(gt);
  const Eigen::Matrix3Xd p_est = positionsOf(est);
  AteResult result;
  if (alignment != Alignment::kNone && !gt.empty())
    result.T_gt_est = umeyamaAlignment(p_est, p_gt, alignment == Alignment::kSim3);
  result.errors.reserve(gt.size());
  for (Eigen::Index k = 0; k < p_gt.cols(); ++k)
    result.errors.push_back((result.T_gt_est.apply(p_est.col(k)) - p_gt.col(k)).norm());
  result.stats = computeStatistics(result.errors);
  return result;
}

}  // namespace lvslam::eval
