#include "report_html.h"

#include <chrono>
#include <filesystem>
#include <iostream>

#include <fmt/format.h>

#include "lvslam/report/run_report_page.h"

namespace lvslam::apps {

void writeRunReportOrWarn(const std::string& run_dir) {
  std::string looked_in;
  const std::optional<report::ReportAssets> assets = report::loadReportAssets(&looked_in);
  if (!assets) {
    std::filesystem::remove(run_dir + "/report.html");  // an earlier run's page would mislead
    std::cerr << report::missingAssetsWarning(run_dir + "/report.html", looked_in);  // warnings on stderr
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  const report::RunReportInfo info = report::writeRunReport(run_dir, *assets);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << fmt::format("wrote {} ({:.1f} MB in {:.2f} s; 3D view: {} of {} map points{})\n", info.path,
                           info.bytes / 1e6, seconds, info.map_points_shown, info.map_points,
                           info.map_voxel_m > 0.0 ? fmt::format(", one per {:.0f} cm voxel", info.map_voxel_m * 100) : "");
}

}  // namespace lvslam::apps
