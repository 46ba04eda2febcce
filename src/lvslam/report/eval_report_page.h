#pragma once
// The report of `lvslam eval --report FILE.html`: the trajectory and error
// plots of the run report for any two TUM files.
#include <string>

#include "lvslam/core/trajectory.h"
#include "lvslam/eval/ate.h"
#include "lvslam/report/report_assets.h"

namespace lvslam::report {

// Throws lvslam::Error when the trajectories do not associate.
void writeEvalReport(const std::string& path, const Trajectory& gt, const std::string& gt_name, const Trajectory& est,
                     const std::string& est_name, eval::Alignment alignment, const ReportAssets& assets);

}  // namespace lvslam::report
