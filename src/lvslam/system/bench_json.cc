#include "lvslam/system/bench_json.h"

#include "lvslam/eval/json_writer.h"

namespace lvslam::system {

namespace {

using eval::JsonObject;

std::string cellJson(const BenchCell& c) {
  JsonObject o;
  if (!c.failure.empty()) return o.addString("failure", c.failure).str();
  o.addNumber("lost_fraction", c.lost_fraction).addNumber("real_time_factor", c.real_time_factor)
      .addNumber("online_real_time_factor", c.online_real_time_factor).addNumber("peak_rss_mib", c.peak_rss_mib);
  const std::pair<const char*, const std::optional<double>*> optional[] = {
      {"ate_mean_m", &c.ate_mean_m},     {"ate_rmse_m", &c.ate_rmse_m},
      {"refined_ate_rmse_m", &c.refined_ate_rmse_m}, {"vision_share", &c.vision_share},
      {"latency_median_ms", &c.latency_median_ms}};
  for (const auto& [key, value] : optional)
    if (*value) o.addNumber(key, **value);
  return o.str();
}

std::string stringArray(const std::vector<std::string>& items) {
  std::string out = "[";
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i) out += ',';
    out += eval::jsonString(items[i]);  // appended apart: `"," + string` trips GCC 12's false -Wrestrict
  }
  return out + "]";
}

}  // namespace

std::string benchGroupJson(const std::string& name, const std::string& note, const std::vector<BenchRow>& rows,
                           const std::vector<std::string>& columns) {
  std::string rows_json = "[";
  for (const BenchRow& row : rows) {
    JsonObject cells;
    for (const std::string& column : columns)
      if (const auto it = row.cells.find(column); it != row.cells.end()) cells.addRaw(column, cellJson(it->second));
    if (rows_json.size() > 1) rows_json += ",";
    rows_json += JsonObject().addString("name", row.sequence).addRaw("cells", cells.str()).str();
  }
  return JsonObject()
      .addString("name", name)
      .addString("note", note)
      .addRaw("columns", stringArray(columns))
      .addRaw("rows", rows_json + "]")
      .str();
}

}  // namespace lvslam::system
