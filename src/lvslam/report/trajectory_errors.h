#pragma once
// Errors of an estimate over time, for the report's plots: the ATE of each
// associated pose after alignment and the RPE of each pose pair 1 m and 10 m
// of path apart (evo's definitions, through eval/), with their statistics.
#include <string>
#include <vector>

#include "lvslam/core/trajectory.h"
#include "lvslam/eval/ate.h"

namespace lvslam::report {

struct ErrorSeries {
  std::string name, unit;
  std::vector<double> t, values;  // t: the estimate's stamp (of the pair's second pose for RPE)
  eval::ErrorStatistics stats;
};

struct TrajectoryErrors {
  eval::Alignment alignment = eval::Alignment::kSE3;
  eval::Similarity3 T_gt_est;        // maps the estimate into the ground truth's world
  std::vector<ErrorSeries> series;  // ATE, then RPE translation and rotation per 1 m and 10 m
};

// Throws lvslam::Error (from eval/) when too few poses associate.
TrajectoryErrors computeTrajectoryErrors(const Trajectory& gt, const Trajectory& est, eval::Alignment alignment,
                                         const std::string& gt_name, const std::string& est_name);

}  // namespace lvslam::report
