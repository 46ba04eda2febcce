#include "lvslam/report/bench_report_page.h"

#include "lvslam/eval/json_writer.h"
#include "lvslam/report/html_page.h"

namespace lvslam::report {

void writeBenchReport(const std::string& path, const std::string& command, const std::vector<std::string>& groups_json,
                      const ReportAssets& assets) {
  std::string groups = "[";
  for (const std::string& group : groups_json) groups += (groups.size() > 1 ? "," : "") + group;
  const std::string title = "lvslam bench: " + command;
  eval::JsonObject data;
  data.addString("kind", "bench").addString("title", title).addRaw("groups", groups + "]");
  writeHtmlFile(path, title, data, assets, false);
}

}  // namespace lvslam::report
