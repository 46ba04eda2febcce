#pragma once
// Trajectory accuracy in one call: associate by time, then ATE (aligned),
// RPE (unaligned, evo's definitions) and the KITTI odometry metric. This is
// what `lvslam eval`, `lvslam run` and `lvslam bench` report.
#include <cstddef>
#include <string>

#include "lvslam/core/trajectory.h"
#include "lvslam/eval/ate.h"
#include "lvslam/eval/kitti_metric.h"
#include "lvslam/eval/rpe.h"

namespace lvslam::eval {

// Fewer associated poses than this cannot be aligned meaningfully.
inline constexpr std::size_t kMinAssociatedPairs = 3;

struct EvalOptions {
  Alignment alignment = Alignment::kSE3;
  double max_dt = 0.02;       // seconds, largest stamp difference of a pair
  double rpe_delta_m = 10.0;  // path length between the poses of an RPE pair
  RpePairsOn rpe_pairs_on = RpePairsOn::kEstimate;  // evo's default
  // Names of the two trajectories (file paths) for error messages.
  std::string gt_name = "ground truth";
  std::string est_name = "estimate";
};

struct EvalResult {
  Alignment alignment = Alignment::kSE3;
  std::size_t pairs = 0;  // associated poses
  AteResult ate;
  RpeResult rpe;             // no pairs when the path is shorter than 2 * delta
  KittiMetric kitti;         // segments of 100..800 m
  KittiMetric kitti_short;   // segments of 1, 5, 10 m
  // The paper's "aligned mean translation error" is the ATE mean.
  double alignedMeanTranslationError() const { return ate.stats.mean; }
};

// Throws lvslam::Error naming both trajectories when fewer than
// kMinAssociatedPairs poses associate or the alignment is degenerate.
EvalResult evaluate(const Trajectory& gt, const Trajectory& est, const EvalOptions& options = {});

}  // namespace lvslam::eval
