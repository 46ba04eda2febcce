#include "lvslam/report/run_report_page.h"

#include <filesystem>
#include <fstream>
#include <optional>

#include "lvslam/core/error.h"
#include "lvslam/eval/evaluate.h"
#include "lvslam/eval/json_writer.h"
#include "lvslam/io/ply_reader.h"
#include "lvslam/io/tum.h"
#include "lvslam/report/html_page.h"
#include "lvslam/report/json_reader.h"
#include "lvslam/report/report_json.h"

namespace lvslam::report {

namespace {

namespace fs = std::filesystem;

// stats.json as text (inlined as it is), after checking that it parses and
// holds what the page draws. Only its summary is held parsed: the per-frame
// arrays (tens of megabytes as a parsed tree on a long run) are checked and
// dropped as they are read.
std::string readStats(const fs::path& path, nlohmann::json& stats) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw Error(path.string(), "cannot read the file (is this a folder `lvslam run` wrote?)");
  std::string text(static_cast<std::size_t>(in.tellg()), '\0');
  in.seekg(0);
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  std::string member;
  stats = parseJson(text, path.string(),
                    [&member](int depth, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
                      if (depth == 1 && event == nlohmann::json::parse_event_t::key) member = parsed.get<std::string>();
                      return depth <= 1 || member == "summary";
                    });
  for (const char* key : {"summary", "frames", "scans", "switches"})
    if (!findMember(stats, key)) throw Error(path.string(), std::string("no \"") + key + "\" field");
  if (!stats.at("summary").is_object()) throw Error(path.string(), "\"summary\" is not an object");
  return text;
}

// The alignment stats.json's accuracy used (sim3 for a visual run without
// metric scale), so the page's figures are the run's.
eval::Alignment alignmentOf(const nlohmann::json& stats) {
  const nlohmann::json* accuracy = findMember(stats.at("summary"), "accuracy");
  const nlohmann::json* align = accuracy ? findMember(*accuracy, "align") : nullptr;
  if (align && *align == "sim3") return eval::Alignment::kSim3;
  if (align && *align == "none") return eval::Alignment::kNone;
  return eval::Alignment::kSE3;
}

// One trajectory of the run, with its errors when there is ground truth.
std::string trajectoryEntry(const std::string& name, const Trajectory& est, const std::optional<Trajectory>& gt,
                            eval::Alignment alignment, const std::string& gt_name) {
  std::optional<TrajectoryErrors> errors;
  if (gt && est.size() >= eval::kMinAssociatedPairs) {
    try {
      errors = computeTrajectoryErrors(*gt, est, alignment, gt_name, name);
    } catch (const Error&) {
      errors.reset();  // too few poses associate: the page shows the trajectory without errors
    }
  }
  eval::JsonObject o;
  o.addRaw("trajectory", trajectoryJson(name, est));
  if (errors) o.addRaw("errors", errorsJson(*errors));
  return o.str();
}

}  // namespace

RunReportInfo writeRunReport(const std::string& run_dir, const ReportAssets& assets) {
  const fs::path dir(run_dir);
  nlohmann::json stats;
  std::string stats_text = readStats(dir / "stats.json", stats);
  const Trajectory online = readTum((dir / "trajectory.tum").string());
  std::optional<Trajectory> refined, gt;
  if (fs::exists(dir / "trajectory_refined.tum")) refined = readTum((dir / "trajectory_refined.tum").string());
  if (fs::exists(dir / "groundtruth.tum")) gt = readTum((dir / "groundtruth.tum").string());
  const eval::Alignment alignment = alignmentOf(stats);

  std::string entries = "[";
  entries += trajectoryEntry("online (trajectory.tum)", online, gt, alignment, "groundtruth.tum");
  if (refined && !refined->empty()) {
    entries += ",";
    entries += trajectoryEntry("refined (trajectory_refined.tum)", *refined, gt, alignment, "groundtruth.tum");
  }
  entries += "]";

  RunReportInfo info;
  eval::JsonObject data;
  data.addString("kind", "run").addString("title", "lvslam run: " + run_dir).addRaw("stats", std::move(stats_text));
  data.addRaw("estimates", entries);
  if (gt) data.addRaw("groundtruth", trajectoryJson("ground truth (groundtruth.tum)", *gt, kGroundTruthDisplayPoses));
  if (fs::exists(dir / "map.ply")) {
    const std::vector<PlyPoint> map = readPointCloudPly((dir / "map.ply").string());
    const DecimatedMap shown = decimateMap(map, kMapPointBudget);
    data.addRaw("map", mapJson(shown, map.size()));
    info.map_points = map.size();
    info.map_points_shown = shown.points.size();
    info.map_voxel_m = shown.voxel_m;
  }
  if (fs::exists(dir / "lines.ply")) data.addRaw("lines", linesJson(readLineSegmentsPly((dir / "lines.ply").string())));

  info.path = (dir / "report.html").string();
  writeHtmlFile(info.path, "lvslam run: " + run_dir, data, assets);
  info.bytes = fs::file_size(info.path);
  return info;
}

}  // namespace lvslam::report
