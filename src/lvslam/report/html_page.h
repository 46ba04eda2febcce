#pragma once
// One self-contained HTML file: the data as JSON and every script inlined,
// so the report opens from disk anywhere, with no server and no network.
#include <ostream>
#include <string>

#include "lvslam/eval/json_writer.h"
#include "lvslam/report/report_assets.h"

namespace lvslam::report {

// `data` is what the page's report.js reads and draws (its "kind": run, eval
// or bench). Without `with_3d` three.js is left out (the page then has no
// 3D view). The page is written piece by piece: a long run's data is tens
// of megabytes, never joined into one string.
void writeHtmlPage(std::ostream& out, const std::string& title, const eval::JsonObject& data,
                   const ReportAssets& assets, bool with_3d = true);
std::string htmlPage(const std::string& title, const eval::JsonObject& data, const ReportAssets& assets,
                     bool with_3d = true);

// Writes the page to `path` through a temporary file and a rename, so a
// failed write never leaves a half page behind. Throws lvslam::Error naming
// the file.
void writeHtmlFile(const std::string& path, const std::string& title, const eval::JsonObject& data,
                   const ReportAssets& assets, bool with_3d = true);

}  // namespace lvslam::report
