#pragma once
// One self-contained HTML file: the data as JSON and every script inlined,
// so the report opens from disk anywhere, with no server and no network.
#include <string>

#include "lvslam/report/report_assets.h"

namespace lvslam::report {

// `data_json` must be a JSON object; the page's report.js reads it and draws
// what it holds (its "kind": run, eval or bench). Without `with_3d` three.js
// is left out (the page then has no 3D view).
std::string htmlPage(const std::string& title, const std::string& data_json, const ReportAssets& assets,
                     bool with_3d = true);

// Writes through a temporary file and a rename, so a failed write never
// leaves a half page behind. Throws lvslam::Error naming the file.
void writeHtmlFile(const std::string& path, const std::string& html);

}  // namespace lvslam::report
