#include "lvslam/system/run_report.h"

#include <filesystem>
#include <fstream>
#include <algorithm>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "lvslam/core/error.h"
#include "lvslam/core/process_memory.h"
#include "lvslam/eval/eval_report.h"
#include "lvslam/eval/json_writer.h"
#include "lvslam/eval/line_accuracy.h"
#include "lvslam/io/tum.h"
#include "lvslam/system/frame_stats_stream.h"
#include "lvslam/system/offline/loop_report.h"

namespace lvslam::system {

namespace {

using eval::JsonObject;

const char* sourceName(OutputSource s) { return s == OutputSource::kVisual ? "visual" : "lidar"; }

// A JSON array of `count` items, one per line, written as each is made
// (stats.json of a long run holds tens of thousands).
template <typename ItemJson>
void writeJsonList(std::ostream& out, std::size_t count, ItemJson item_json) {
  out << '[';
  for (std::size_t i = 0; i < count; ++i) out << (i ? ",\n  " : "\n  ") << item_json(i);
  out << (count == 0 ? "]" : "\n]");
}

std::string visualJson(const VisualFrameRecord& v) {
  const visual::VisualFrameResult& r = v.result;
  JsonObject o;
  o
      .addString("state", visual::trackingStateName(r.state))
      .addRaw("pose", r.pose_valid ? "true" : "false")
      .addNumber("map_id", r.map_id)
      .addRaw("keyframe", r.keyframe ? "true" : "false")
      .addNumber("keypoints", r.health.keypoints)
      .addNumber("segments", r.health.segments)
      .addNumber("tracked_points", r.health.tracked_points)
      .addNumber("tracked_lines", r.health.tracked_lines)
      .addNumber("inlier_ratio", r.health.inlier_ratio)
      .addNumber("brightness", r.health.brightness)
      .addNumber("contrast", r.health.contrast)
      .addNumber("fusion_lines_added", v.fusion_lines_added)
      .addCount("keypoint_depths", v.keypoint_depths);  // from the raw scans
  if (r.fusion.anchor_time) o.addNumber("landmark_age_s", r.timestamp - *r.fusion.anchor_time);  // map reuse shows here
  return o.str();
}

std::string frameJson(const PipelineRecords& records, std::size_t j, bool timings) {
  // The online part is what stats_frames.jsonl streamed during the run.
  JsonObject o = onlineFrameJson(records.online[j], timings);
  const std::optional<VisualFrameRecord> visual = records.visual.get(j);
  const std::optional<LidarFrameRecord> lidar = records.lidar.get(j);
  const VisualFrameRecord* v = visual ? &*visual : nullptr;
  const LidarFrameRecord* l = lidar ? &*lidar : nullptr;
  if (v) o.addRaw("visual", visualJson(*v));
  if (l && v)
    o.addRaw("fusion", JsonObject()
                           .addCount("lines", l->fusion_lines.size())
                           .addCount("lidar_features", l->lidar_features)
                           .addCount("lidar_points_refined", l->lidar_points_refined)
                           .addCount("keypoint_depths", l->keypoint_depths)
                           .str());
  if (timings) {
    JsonObject t;
    if (v) t.addNumber("extraction", v->extract_ms).addNumber("depth_hints", v->hints_ms).addNumber("visual", v->track_ms);
    if (l && v) t.addNumber("fusion", l->fusion_ms).addNumber("fusion_lines_to_visual", v->fusion_apply_ms);
    o.addRaw("time_ms", t.str());
  }
  return o.str();
}

std::string scanJson(const ScanRecord& s, bool timings) {
  JsonObject o;
  o.addNumber("t", s.t)
      .addString("status", s.status)
      .addCount("features", s.features)
      .addRaw("features_per_class", fmt::format("[{}]", fmt::join(s.features_per_class, ",")))
      .addCount("correspondences", s.correspondences)
      .addNumber("iterations", s.iterations);
  if (timings) o.addRaw("time_ms", JsonObject().addNumber("prepare", s.prepare_ms).addNumber("register", s.register_ms).str());
  return o.str();
}

std::string extrinsicCheckJson(const fusion::ExtrinsicVerdict& v) {
  const auto degrees = [](const Eigen::Vector3d& w) { return eval::jsonArray({w.x() * 180.0 / M_PI, w.y() * 180.0 / M_PI, w.z() * 180.0 / M_PI}); };
  return JsonObject()
      .addNumber("t_first", v.t_first)
      .addNumber("t_last", v.t_last)
      .addNumber("frames", v.frames)
      .addCount("associations", v.associations)
      .addRaw("window_rotation_deg", degrees(v.window_rotation))
      .addNumber("windows", v.windows)
      .addRaw("mean_rotation_deg", degrees(v.rotation))
      .addNumber("misalignment_deg", v.misalignment_deg)
      .addNumber("sigma_deg", v.sigma_deg)
      .addRaw("misaligned", v.misaligned ? "true" : "false")
      .str();
}

std::string summaryJson(const RunSummary& s, const RunAccuracy& accuracy, bool timings) {
  JsonObject o;
  o.addString("mode", runModeName(s.mode))
      .addCount("images", s.images)
      .addCount("scans", s.scans)
      .addCount("poses", s.poses)
      .addCount("visual_output_frames", s.visual_output)
      .addCount("fused_output_frames", s.fused_output)
      .addCount("visual_tracked_frames", s.visual_tracked)
      .addCount("visual_maps", s.visual_maps)
      .addCount("switches", s.switches)
      .addNumber("fusion_lines_per_frame", s.fusion_lines_per_frame)
      .addNumber("sequence_seconds", s.sequence_seconds)
      .addNumber("lost_fraction", s.lost_fraction)
      .addCount("gated_lidar_factors", s.gated_lidar)
      .addCount("gated_visual_factors", s.gated_visual)
      .addNumber("visual_consistency_first", s.visual_consistency_first)
      .addNumber("visual_consistency_last", s.visual_consistency_last);
  if (!s.stopped_why.empty())
    o.addRaw("stopped", JsonObject()
                            .addString("where", s.stopped_where)
                            .addString("why", s.stopped_why)
                            .addNumber("after_t", s.stopped_after_t)
                            .str());
  if (accuracy.online) o.addRaw("accuracy", eval::formatJson(*accuracy.online));
  if (accuracy.refined) o.addRaw("accuracy_refined", eval::formatJson(*accuracy.refined));
  if (timings)
    o.addNumber("wall_seconds", s.wall_seconds)
        .addNumber("real_time_factor", s.real_time_factor)
        .addNumber("online_seconds", s.online_seconds)
        .addNumber("online_real_time_factor", s.online_real_time_factor)
        .addNumber("peak_rss_mib", s.peak_rss_mib)
        .addRaw("latency_ms", JsonObject()
                                  .addNumber("median", s.latency_median_ms)
                                  .addNumber("p95", s.latency_p95_ms)
                                  .addNumber("max", s.latency_max_ms)
                                  .str());
  return o.str();
}

double lostFraction(const PipelineRecords& records, RunMode mode) {
  const auto share = [](std::size_t part, std::size_t whole) {
    return whole == 0 ? 1.0 : static_cast<double>(part) / static_cast<double>(whole);
  };
  if (mode == RunMode::kLidar) {
    std::size_t lost = 0;
    for (const ScanRecord& scan : records.scans) lost += scan.status == "lost" || scan.status == "rejected";
    return share(lost, records.scans.size());
  }
  std::size_t missing = 0;
  if (mode == RunMode::kVisual)
    for (const VisualFrameRecord& v : records.visual) missing += !v.result.pose_valid;
  else
    for (const FrameOutput& f : records.online) missing += !f.T_world_camera;
  return share(missing, records.images);
}

// Mean of the frames' visual consistency (-1: none) over [begin, end), -1 without any.
double meanConsistency(const std::vector<double>& chi_square_per_dof, std::size_t begin, std::size_t end) {
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t j = begin; j < end; ++j)
    if (chi_square_per_dof[j] >= 0.0) {
      sum += chi_square_per_dof[j];
      ++count;
    }
  return count == 0 ? -1.0 : sum / static_cast<double>(count);
}

void addOnlineFigures(const RecordFile<FrameOutput>& frames, RunSummary& s) {
  std::vector<double> latencies, consistency;
  for (const FrameOutput& f : frames) {
    latencies.push_back(f.latency_ms);
    consistency.push_back(f.visual_chi_square_per_dof);
    for (const GateEvent& g : f.gated) (g.source == FactorSource::kLidar ? s.gated_lidar : s.gated_visual) += 1;
  }
  s.latency_median_ms = eval::quantile(latencies, 0.5);
  s.latency_p95_ms = eval::quantile(latencies, 0.95);
  s.latency_max_ms = latencies.empty() ? 0.0 : *std::max_element(latencies.begin(), latencies.end());
  const std::size_t n = consistency.size();
  s.visual_consistency_first = meanConsistency(consistency, 0, n / 3);
  s.visual_consistency_last = meanConsistency(consistency, n - n / 3, n);
}

}  // namespace

RunSummary summarize(const PipelineRecords& records, const SystemOutput& output, RunMode mode, double online_seconds,
                     double wall_seconds) {
  RunSummary s;
  s.mode = mode;
  s.images = records.images;
  s.scans = records.scans_read;
  if (records.input_fault) {
    s.stopped_where = records.input_fault->where();
    s.stopped_why = records.input_fault->why();
    s.stopped_after_t = records.last_time;
  }
  for (const ScanRecord& scan : records.scans) ++s.lidar_statuses[scan.status];
  s.poses = output.trajectory.size();
  std::set<int> maps;
  for (const VisualFrameRecord& v : records.visual) {
    s.visual_tracked += v.result.pose_valid ? 1 : 0;
    if (v.result.pose_valid) maps.insert(v.result.map_id);
  }
  s.visual_maps = maps.size();
  if (mode == RunMode::kFused)
    for (const FrameOutput& f : records.online) {
      s.visual_output += f.source == OutputSource::kVisual && f.T_world_camera;
      s.fused_output += f.fused && f.T_world_camera;
    }
  if (mode == RunMode::kVisual) s.visual_output = s.visual_tracked;
  std::size_t lines = 0;
  for (const LidarFrameRecord& l : records.lidar) lines += l.fusion_lines.size();
  s.fusion_lines_per_frame = records.lidar.empty() ? 0.0 : static_cast<double>(lines) / records.lidar.size();
  s.switches = output.switches.size();
  s.lost_fraction = lostFraction(records, mode);
  addOnlineFigures(records.online, s);
  s.sequence_seconds = records.last_time - records.first_time;
  s.wall_seconds = wall_seconds;
  s.real_time_factor = wall_seconds > 0.0 ? s.sequence_seconds / wall_seconds : 0.0;
  s.online_seconds = online_seconds;
  s.online_real_time_factor = online_seconds > 0.0 ? s.sequence_seconds / online_seconds : 0.0;
  s.peak_rss_mib = peakResidentMiB();
  return s;
}

std::string formatRunSummary(const RunSummary& s, const SystemOutput& output) {
  std::string text = fmt::format("mode {}: {} images, {} scans, {:.1f} s of data in {:.1f} s ({:.2f}x real time; "
                                 "online {:.1f} s, {:.2f}x), peak memory {:.0f} MiB\n",
                                 runModeName(s.mode), s.images, s.scans, s.sequence_seconds, s.wall_seconds,
                                 s.real_time_factor, s.online_seconds, s.online_real_time_factor, s.peak_rss_mib);
  if (s.images > 0)
    text += fmt::format("online output latency: median {:.1f} ms, p95 {:.1f} ms, max {:.1f} ms\n", s.latency_median_ms,
                        s.latency_p95_ms, s.latency_max_ms);
  if (!s.lidar_statuses.empty()) {
    text += "lidar subsystem:";
    for (const auto& [status, count] : s.lidar_statuses) text += fmt::format(" {} {},", status, count);
    text.back() = '\n';
  }
  if (s.mode != RunMode::kLidar)
    text += fmt::format("visual subsystem: tracked {} of {} frames ({:.1f} %), {} map(s)\n", s.visual_tracked,
                        s.images, 100.0 * s.visual_tracked / std::max<std::size_t>(s.images, 1), s.visual_maps);
  if (s.mode == RunMode::kFused) {
    text += fmt::format("fusion: {:.2f} fusion lines per frame; vision entered the online pose of {} of {} frames "
                        "({} with the LiDAR's), {} switch(es); gate dropped {} LiDAR and {} visual factors\n",
                        s.fusion_lines_per_frame, s.visual_output, s.images, s.fused_output, s.switches,
                        s.gated_lidar, s.gated_visual);
    for (const SwitchEvent& e : output.switches)
      text += fmt::format("  t={:.3f} -> {}: {}\n", e.t, sourceName(e.to), e.reason);
  }
  return text;
}

namespace {

// stats.json, streamed: its members in the order a reader finds them.
void writeStatsJson(const std::filesystem::path& path, const PipelineRecords& records, const SystemOutput& output,
                    const std::string& summary_json, bool with_timings) {
  std::ofstream file(path);
  bool first = true;
  const auto member = [&file, &first](std::string_view key) -> std::ostream& {
    file << (first ? "{" : ", ") << eval::jsonString(key) << ": ";
    first = false;
    return file;
  };
  member("summary") << summary_json;
  writeJsonList(member("switches"), output.switches.size(), [&output](std::size_t i) {
    const SwitchEvent& e = output.switches[i];
    return JsonObject().addNumber("t", e.t).addString("to", sourceName(e.to)).addString("reason", e.reason).str();
  });
  writeJsonList(member("frames"), records.online.size(),
                [&](std::size_t j) { return frameJson(records, j, with_timings); });
  writeJsonList(member("scans"), records.scans.size(),
                [&](std::size_t i) { return scanJson(records.scans[i], with_timings); });
  if (output.loop) member("loop") << loopJson(*output.loop);
  if (!records.extrinsic_checks.empty())
    writeJsonList(member("extrinsic_check"), records.extrinsic_checks.size(),
                  [&records](std::size_t i) { return extrinsicCheckJson(records.extrinsic_checks[i]); });
  file << "}\n";
  if (!file) throw Error(path.string(), "cannot write the file");
}

}  // namespace

void writeRunOutputs(const std::string& out_dir, const PipelineRecords& records, const SystemOutput& output,
                     const RunSummary& summary, const RunAccuracy& accuracy, bool with_timings) {
  const std::filesystem::path dir(out_dir);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Error(out_dir, "cannot create the output folder: " + ec.message());
  writeTum((dir / "trajectory.tum").string(), output.trajectory);
  writeTum((dir / "trajectory_refined.tum").string(), output.trajectory_refined);
  if (!output.trajectory_in_map.empty()) writeTum((dir / "trajectory_in_map.tum").string(), output.trajectory_in_map);
  if (!output.visual_maps.empty() || !output.lidar_camera.empty()) {
    const std::filesystem::path own = dir / "subsystems";
    std::filesystem::create_directories(own, ec);
    if (ec) throw Error(own.string(), "cannot create the folder: " + ec.message());
    for (const auto& [id, poses] : output.visual_maps)
      writeTum((own / fmt::format("visual_map_{}.tum", id)).string(), poses);
    if (!output.lidar_camera.empty()) writeTum((own / "lidar_camera.tum").string(), output.lidar_camera);
  }
  writeStatsJson(dir / "stats.json", records, output, summaryJson(summary, accuracy, with_timings), with_timings);
  writePointCloudPly((dir / "map.ply").string(), output.lidar_map);
  writeLineSegmentsPly((dir / "lines.ply").string(), output.lines_world);
}

}  // namespace lvslam::system
