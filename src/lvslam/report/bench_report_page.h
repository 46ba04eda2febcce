#pragma once
// bench.html of `lvslam bench`: its tables, with bars per mode.
#include <string>
#include <vector>

#include "lvslam/report/report_assets.h"

namespace lvslam::report {

// `groups_json`: one JSON object per table (system/bench_json.h).
void writeBenchReport(const std::string& path, const std::string& command, const std::vector<std::string>& groups_json,
                      const ReportAssets& assets);

}  // namespace lvslam::report
