#pragma once
// The JavaScript and CSS a report inlines: three.js with its OrbitControls,
// Chart.js (from web/node_modules, pinned by web/package-lock.json) and the
// page's own report.js / report.css, copied by CMake into
// build/share/lvslam/report/. Looked up in $LVSLAM_REPORT_ASSETS when set
// (and only there), else beside the binary (../share/lvslam/report), else in
// the build tree the binary was built in.
#include <optional>
#include <string>

namespace lvslam::report {

struct ReportAssets {
  std::string dir;
  std::string three_js, orbit_controls_js, chart_js, report_js, report_css;
};

// Empty when no candidate folder holds every file; `looked_in` then lists
// the folders tried.
std::optional<ReportAssets> loadReportAssets(std::string* looked_in = nullptr);

// Why a report cannot be written without them, and how to install them.
std::string missingAssetsReason(const std::string& looked_in);
// The one line `lvslam run` and `lvslam bench` print when the assets are missing.
std::string missingAssetsWarning(const std::string& file, const std::string& looked_in);

}  // namespace lvslam::report
