#include "lvslam/eval/rpe.h"

#include <numbers>

#include <fmt/format.h>

#include "lvslam/core/error.h"
#include "lvslam/core/se3.h"

namespace lvslam::eval {

std::vector<PoseIndexPair> consecutivePairsByPath(const std::vector<Eigen::Isometry3d>& poses,
                                                  double delta_m) {
  std::vector<std::size_t> marks;
  double path_since_mark = 0.0;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    if (i > 0) path_since_mark += (poses[i].translation() - poses[i - 1].translation()).norm();
    if (path_since_mark >= delta_m) {
      marks.push_back(i);
      path_since_mark = 0.0;
    }
  }
  std::vector<PoseIndexPair> pairs;
  for (std::size_t k = 1; k < marks.size(); ++k) pairs.emplace_back(marks[k - 1], marks[k]);
  return pairs;
}

std::string rpePairsOnName(RpePairsOn pairs_on) {
  return pairs_on == RpePairsOn::kEstimate ? "est" : "gt";
}

RpeResult computeRpe(const std::vector<Eigen::Isometry3d>& gt,
                     const std::vector<Eigen::Isometry3d>& est, double delta_m,
                     RpePairsOn pairs_on) {
  if (gt.size() != est.size())
    throw Error("RPE", fmt::format("pose lists differ in length ({} ground truth, {} estimated)",
                                   gt.size(), est.size()));
  RpeResult result;
  result.delta_m = delta_m;
  result.pairs_on = pairs_on;
  result.pairs = consecutivePairsByPath(pairs_on == RpePairsOn::kEstimate ? est : gt, delta_m);
  for (const auto& [i, j] : result.pairs) {
    const Eigen::Isometry3d gt_motion = gt[i].inverse() * gt[j];
    const Eigen::Isometry3d est_motion = est[i].inverse() * est[j];
    const Eigen::Isometry3d error = gt_motion.inverse() * est_motion;
    result.translation_errors.push_back(error.translation().norm());
    result.rotation_errors_deg.push_back(rotationAngle(error) * 180.0 / std::numbers::pi);
  }
  result.translation = computeStatistics(result.translation_errors);
  result.rotation_deg = computeStatistics(result.rotation_errors_deg);
  return result;
}

}  // namespace lvslam::eval
