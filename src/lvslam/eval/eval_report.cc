#include "lvslam/eval/eval_report.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "lvslam/eval/json_writer.h"

namespace lvslam::eval {

namespace {

std::string statisticsLine(const ErrorStatistics& s) {
  return fmt::format("rmse {:.6f}  mean {:.6f}  median {:.6f}  std {:.6f}  min {:.6f}  max {:.6f}",
                     s.rmse, s.mean, s.median, s.std_dev, s.min, s.max);
}

std::string lengthsText(const KittiMetric& metric) {
  return fmt::format("{}", fmt::join(metric.lengths_m, ","));
}

std::string kittiLine(const KittiMetric& metric) {
  if (metric.segments == 0)
    return fmt::format("KITTI metric ({} m): no segments (path too short)\n", lengthsText(metric));
  return fmt::format("KITTI metric ({} m): translation {:.4f} %, rotation {:.6f} deg/m ({} segments)\n",
                     lengthsText(metric), metric.translation_percent, metric.rotation_deg_per_m,
                     metric.segments);
}

// Adds rmse, mean, median, max, std, min as fields of `json`.
JsonObject& addStatistics(JsonObject& json, const ErrorStatistics& s) {
  json.addNumber("rmse", s.rmse).addNumber("mean", s.mean).addNumber("median", s.median);
  return json.addNumber("max", s.max).addNumber("std", s.std_dev).addNumber("min", s.min);
}

std::string statisticsJson(const ErrorStatistics& s) {
  JsonObject json;
  return addStatistics(json, s).str();
}

std::string kittiJson(const KittiMetric& metric) {
  if (metric.segments == 0) return "null";
  return JsonObject()
      .addRaw("lengths_m", jsonArray(metric.lengths_m))
      .addCount("segments", metric.segments)
      .addNumber("translation_percent", metric.translation_percent)
      .addNumber("rotation_deg_per_m", metric.rotation_deg_per_m)
      .str();
}

// The translation statistics sit directly in "rpe", the rotation ones in "rot_deg".
std::string rpeJson(const RpeResult& rpe) {
  JsonObject json;
  json.addNumber("delta_m", rpe.delta_m).addString("pairs_on", rpePairsOnName(rpe.pairs_on));
  json.addCount("count", rpe.translation.count);
  addStatistics(json, rpe.translation);
  return json.addRaw("rot_deg", statisticsJson(rpe.rotation_deg)).str();
}

}  // namespace

std::string formatSummary(const EvalResult& r) {
  std::string out;
  out += fmt::format("associated poses: {}  alignment: {}  scale: {:.6f}\n", r.pairs,
                     alignmentName(r.alignment), r.ate.T_gt_est.scale);
  out += fmt::format("aligned mean translation error: {:.6f} m\n", r.alignedMeanTranslationError());
  out += fmt::format("ATE (m):            {}\n", statisticsLine(r.ate.stats));
  if (r.rpe.translation.count == 0) {
    out += fmt::format("RPE ({} m): no pairs (path shorter than twice the delta)\n", r.rpe.delta_m);
  } else {
    out += fmt::format("RPE {} m (m):       {}  ({} pairs on the {} path)\n", r.rpe.delta_m,
                       statisticsLine(r.rpe.translation), r.rpe.translation.count,
                       r.rpe.pairs_on == RpePairsOn::kEstimate ? "estimated" : "ground-truth");
    out += fmt::format("RPE {} m (deg):     {}\n", r.rpe.delta_m, statisticsLine(r.rpe.rotation_deg));
  }
  out += kittiLine(r.kitti);
  out += kittiLine(r.kitti_short);
  return out;
}

std::string formatJson(const EvalResult& r) {
  const std::string kitti = JsonObject()
                                .addRaw("lengths_100_800m", kittiJson(r.kitti))
                                .addRaw("lengths_1_10m", kittiJson(r.kitti_short))
                                .str();
  return JsonObject()
      .addCount("pairs", r.pairs)
      .addString("align", alignmentName(r.alignment))
      .addNumber("scale", r.ate.T_gt_est.scale)
      .addRaw("ate", statisticsJson(r.ate.stats))
      .addRaw("rpe", rpeJson(r.rpe))
      .addRaw("kitti", kitti)
      .addNumber("aligned_mean_translation_error", r.alignedMeanTranslationError())
      .str();
}

}  // namespace lvslam::eval
