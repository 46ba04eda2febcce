#include "lvslam/report/eval_report_page.h"

#include "lvslam/eval/json_writer.h"
#include "lvslam/report/html_page.h"
#include "lvslam/report/report_json.h"
#include "lvslam/report/trajectory_errors.h"

namespace lvslam::report {

void writeEvalReport(const std::string& path, const Trajectory& gt, const std::string& gt_name, const Trajectory& est,
                     const std::string& est_name, eval::Alignment alignment, const ReportAssets& assets) {
  const TrajectoryErrors errors = computeTrajectoryErrors(gt, est, alignment, gt_name, est_name);
  const std::string entry = eval::JsonObject()
                                .addRaw("trajectory", trajectoryJson(est_name, est))
                                .addRaw("errors", errorsJson(errors))
                                .str();
  const std::string title = "lvslam eval: " + est_name + " against " + gt_name;
  eval::JsonObject data;
  data.addString("kind", "eval")
      .addString("title", title)
      .addRaw("estimates", "[" + entry + "]")
      .addRaw("groundtruth", trajectoryJson(gt_name, gt, kGroundTruthDisplayPoses));
  writeHtmlFile(path, title, data, assets);
}

}  // namespace lvslam::report
