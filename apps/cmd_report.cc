// `lvslam report OUT_DIR`: (re)builds report.html from a folder `lvslam run`
// wrote, one self-contained page of its trajectories, errors, records and map.
#include <memory>
#include <string>

#include <fmt/format.h>

#include "command.h"
#include "report_html.h"
#include "lvslam/core/error.h"
#include "lvslam/report/run_report_page.h"

namespace lvslam::apps {

namespace {

int runReport(const std::string& run_dir) {
  std::string looked_in;
  if (!report::loadReportAssets(&looked_in))
    throw Error(run_dir + "/report.html", "not written: " + report::missingAssetsReason(looked_in));
  writeRunReportOrWarn(run_dir);
  return 0;
}

}  // namespace

void addReportCommand(CLI::App& app, CommandAction& action) {
  CLI::App* cmd = app.add_subcommand(
      "report", "Write OUT_DIR/report.html from a folder `lvslam run` wrote (stats.json, trajectory.tum, "
                "trajectory_refined.tum, groundtruth.tum, map.ply, lines.ply): one self-contained page, opened from "
                "disk with no server, of the trajectories, errors, detection module, fusion, timings and a 3D view");
  auto run_dir = std::make_shared<std::string>();
  cmd->add_option("OUT_DIR", *run_dir, "Output folder of `lvslam run`")->required();
  cmd->callback([&action, run_dir] { action = [run_dir] { return runReport(*run_dir); }; });
}

}  // namespace lvslam::apps
