#include "lvslam/report/trajectory_errors.h"

#include <fmt/format.h>

#include "lvslam/core/error.h"
#include "lvslam/eval/association.h"
#include "lvslam/eval/evaluate.h"
#include "lvslam/eval/rpe.h"

namespace lvslam::report {

namespace {

void addRpe(const eval::AssociatedPoses& poses, const Trajectory& est, const std::vector<eval::IndexPair>& pairs,
            double delta_m, TrajectoryErrors& out) {
  const eval::RpeResult rpe = eval::computeRpe(poses.gt, poses.est, delta_m);
  ErrorSeries trans{fmt::format("RPE {:g} m, translation", delta_m), "m", {}, rpe.translation_errors, rpe.translation};
  ErrorSeries rot{fmt::format("RPE {:g} m, rotation", delta_m), "deg", {}, rpe.rotation_errors_deg, rpe.rotation_deg};
  for (const eval::PoseIndexPair& pair : rpe.pairs) trans.t.push_back(est[pairs[pair.second].est_index].t);
  rot.t = trans.t;
  out.series.push_back(std::move(trans));
  out.series.push_back(std::move(rot));
}

}  // namespace

TrajectoryErrors computeTrajectoryErrors(const Trajectory& gt, const Trajectory& est, eval::Alignment alignment,
                                         const std::string& gt_name, const std::string& est_name) {
  eval::EvalOptions defaults;
  const std::vector<eval::IndexPair> pairs = eval::associateByTime(gt, est, defaults.max_dt);
  if (pairs.size() < eval::kMinAssociatedPairs)
    throw Error(gt_name + " vs " + est_name, fmt::format("only {} poses associate within {} s", pairs.size(), defaults.max_dt));
  const eval::AssociatedPoses poses = eval::selectPairs(gt, est, pairs);
  const eval::AteResult ate = eval::computeAte(poses.gt, poses.est, alignment);
  TrajectoryErrors out;
  out.alignment = alignment;
  out.T_gt_est = ate.T_gt_est;
  ErrorSeries ate_series{"ATE (" + eval::alignmentName(alignment) + " aligned)", "m", {}, ate.errors, ate.stats};
  for (const eval::IndexPair& pair : pairs) ate_series.t.push_back(est[pair.est_index].t);
  out.series.push_back(std::move(ate_series));
  for (double delta_m : {1.0, 10.0}) addRpe(poses, est, pairs, delta_m, out);
  return out;
}

}  // namespace lvslam::report
