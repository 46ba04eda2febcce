#pragma once
// What a run hands the user: trajectory.tum, stats.json (per frame and per
// scan: stage times, subsystem in use, features, fusion lines), map.ply (the
// LiDAR map), lines.ply (the 3D line map), the subsystems' own trajectories
// and a summary of figures that the CLI prints and `lvslam bench` tabulates.
#include <map>
#include <optional>
#include <string>

#include "lvslam/eval/evaluate.h"

#include "lvslam/system/output_assembly.h"
#include "lvslam/system/system_pipeline.h"

namespace lvslam::system {

struct RunSummary {
  RunMode mode = RunMode::kFused;
  std::size_t images = 0, scans = 0;
  std::map<std::string, std::size_t> lidar_statuses;  // scans per odometry status
  std::size_t poses = 0;           // output poses written
  std::size_t visual_output = 0;   // camera frames whose output came from vision
  std::size_t fused_output = 0;    // of those, the ones fused with the LiDAR pose (output fusion)
  std::size_t visual_tracked = 0;  // camera frames the visual subsystem tracked
  std::size_t visual_maps = 0;     // maps the visual subsystem started
  std::size_t switches = 0;
  double fusion_lines_per_frame = 0.0;
  double sequence_seconds = 0.0;   // span of the sensor data
  double wall_seconds = 0.0;       // the whole run: online pipeline, then the offline step
  double real_time_factor = 0.0;   // sequence seconds per wall second
  // The online pipeline alone (reading, both subsystems, the online
  // output, up to the last frame's pose): the pace a live robot needs. The
  // rest of wall_seconds is the loop closure's last solve, the offline
  // refinement and the outputs assembled after the last frame.
  double online_seconds = 0.0;
  double online_real_time_factor = 0.0;
  double peak_rss_mib = 0.0;       // of the whole process so far
  // Share of the mode's frames without an estimate: scans the LiDAR lost
  // (lidar), frames vision did not track (visual), frames without output
  // (fused). Above one half the paper's tables print x.
  double lost_fraction = 0.0;
  // Online output latency per camera frame (output wall time minus the
  // frame's arrival), milliseconds.
  double latency_median_ms = 0.0, latency_p95_ms = 0.0, latency_max_ms = 0.0;
  // Factors the fused estimator's chi-square gate dropped, per subsystem.
  std::size_t gated_lidar = 0, gated_visual = 0;
  // Sensor-to-sensor consistency: mean chi^2 per degree of freedom of the
  // accepted visual factors in the first and the last third of the run
  // (about 1 when both subsystems' covariances are right; a steady rise
  // points at the extrinsic or the time offset). -1: none.
  double visual_consistency_first = -1.0, visual_consistency_last = -1.0;
  // Where and why the recording could not be read further (empty when it was
  // read whole), and the time of the last data read before it.
  std::string stopped_where, stopped_why;
  double stopped_after_t = 0.0;
};

RunSummary summarize(const PipelineRecords& records, const SystemOutput& output, RunMode mode, double online_seconds,
                     double wall_seconds);

// Several lines for the terminal, ending in a newline.
std::string formatRunSummary(const RunSummary& summary, const SystemOutput& output);

// Writes trajectory.tum (online), trajectory_refined.tum (offline
// refinement), stats.json, map.ply and lines.ply into out_dir (created), and the subsystems' own
// trajectories into out_dir/subsystems: visual_map_<id>.tum (T_map_camera in
// the frame of visual map <id>) and, in fused mode, lidar_camera.tum. Without
// timings (for --deterministic) stats.json has no wall-clock figures, so runs
// compare byte for byte.
// The accuracy, when given, goes into the summary of stats.json.
struct RunAccuracy {
  std::optional<eval::EvalResult> online, refined;
};
void writeRunOutputs(const std::string& out_dir, const PipelineRecords& records, const SystemOutput& output,
                     const RunSummary& summary, const RunAccuracy& accuracy, bool with_timings);

}  // namespace lvslam::system
