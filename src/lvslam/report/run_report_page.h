#pragma once
// report.html of a run folder: everything `lvslam run` wrote (stats.json,
// trajectory.tum, trajectory_refined.tum, map.ply, lines.ply and, when the
// recording had ground truth, groundtruth.tum) in one page.
#include <cstddef>
#include <string>

#include "lvslam/report/report_assets.h"

namespace lvslam::report {

struct RunReportInfo {
  std::string path;            // the report written
  std::size_t bytes = 0;
  std::size_t map_points = 0, map_points_shown = 0;
  double map_voxel_m = 0.0;    // 0: every map point shown
};

// The most map points the 3D view gets (see map_decimation.h).
inline constexpr std::size_t kMapPointBudget = 250000;

// Throws lvslam::Error naming the file when stats.json or trajectory.tum is
// missing or broken (the page is then not written).
RunReportInfo writeRunReport(const std::string& run_dir, const ReportAssets& assets);

}  // namespace lvslam::report
