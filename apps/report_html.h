#pragma once
// report.html after a run (cmd_run.cc) and on its own (`lvslam report`,
// cmd_report.cc, which defines this).
#include <string>

namespace lvslam::apps {

// Writes run_dir/report.html and prints one line: what was written (size,
// seconds), or, when the JavaScript assets are missing, a warning that says
// how to install them (the run itself still succeeds).
void writeRunReportOrWarn(const std::string& run_dir);

}  // namespace lvslam::apps
