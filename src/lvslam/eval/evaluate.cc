#include "lvslam/eval/evaluate.h"

#include <fmt/format.h>

#include "lvslam/core/error.h"
#include "lvslam/eval/association.h"

namespace lvslam::eval {

EvalResult evaluate(const Trajectory& gt, const Trajectory& est, const EvalOptions& options) {
  const std::string both = fmt::format("{} vs {}", options.gt_name, options.est_name);
  if (!(options.max_dt >= 0.0) || !(options.rpe_delta_m > 0.0))
    throw Error(both, fmt::format("max_dt must be >= 0 and the RPE delta > 0 (got {} s, {} m)",
                                  options.max_dt, options.rpe_delta_m));
  const std::vector<IndexPair> pairs = associateByTime(gt, est, options.max_dt);
  if (pairs.size() < kMinAssociatedPairs)
    throw Error(both, fmt::format("only {} poses associate within {} s ({} and {} poses); need at "
                                  "least {} (do the time stamps share a clock?)",
                                  pairs.size(), options.max_dt, gt.size(), est.size(),
                                  kMinAssociatedPairs));
  const AssociatedPoses poses = selectPairs(gt, est, pairs);

  EvalResult result;
  result.alignment = options.alignment;
  result.pairs = pairs.size();
  try {
    result.ate = computeAte(poses.gt, poses.est, options.alignment);
  } catch (const Error& e) {
    throw Error(both, e.what());
  }
  result.rpe = computeRpe(poses.gt, poses.est, options.rpe_delta_m, options.rpe_pairs_on);
  result.kitti = computeKittiMetric(poses.gt, poses.est, kKittiLengthsM);
  result.kitti_short = computeKittiMetric(poses.gt, poses.est, kShortLengthsM);
  return result;
}

}  // namespace lvslam::eval
