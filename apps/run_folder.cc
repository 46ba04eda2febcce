#include "run_folder.h"

#include <filesystem>
#include <iostream>
#include <stdexcept>

#include <fmt/format.h>

#include "report_html.h"
#include "lvslam/core/process_memory.h"
#include "lvslam/eval/eval_report.h"
#include "lvslam/io/tum.h"
#include "lvslam/system/ground_truth_export.h"
#include "lvslam/system/offline/loop_report.h"

namespace lvslam::apps {

void finishRunFolder(const std::string& out_dir, Recording& recording, system::RunResult run, const std::string& mode,
                     bool deterministic) {
  // Input that ends in a fault (a cut last scan or image) still gives what was
  // read before it: the outputs are written, then the fault is the one error line.
  if (run.output.trajectory.empty()) {  // no result: the streams' files go
    std::filesystem::remove(out_dir + "/trajectory.tum");
    std::filesystem::remove(out_dir + "/stats_frames.jsonl");
  }
  if (run.output.trajectory.empty() && run.records.input_fault) throw *run.records.input_fault;
  if (run.output.trajectory.empty())
    throw std::runtime_error(fmt::format("no result: mode {} gave no pose from {} images and {} scans", mode,
                                         run.summary.images, run.summary.scans));
  system::writeRunOutputs(out_dir, run.records, run.output, run.summary, {run.accuracy, run.accuracy_refined},
                          !deterministic);
  std::cout << system::formatRunSummary(run.summary, run.output);
  if (run.output.loop && run.records.loop)
    std::cout << system::formatLoopSummary(*run.output.loop, *run.records.loop);
  std::cout << fmt::format("wrote {}/{{trajectory.tum (online {}, {} poses), trajectory_refined.tum (offline, {} poses), "
                           "stats.json, map.ply ({} points), lines.ply ({} lines)}}\n",
                           out_dir, run.output.trajectory_is_camera ? "T_world_camera" : "T_world_lidar",
                           run.output.trajectory.size(), run.output.trajectory_refined.size(),
                           run.output.lidar_map.size(), run.output.lines_world.size());
  if (run.accuracy) std::cout << "online (trajectory.tum):\n" << eval::formatSummary(*run.accuracy);
  if (run.accuracy_refined)
    std::cout << "offline refinement (trajectory_refined.tum):\n" << eval::formatSummary(*run.accuracy_refined);
  // No stale file from an earlier run into the same folder may reach the report.
  if (const std::optional<Trajectory> gt = system::groundTruthInOutputFrame(recording, run.output))
    writeTum(out_dir + "/groundtruth.tum", *gt);
  else
    std::filesystem::remove(out_dir + "/groundtruth.tum");
  const std::optional<Error> fault = std::move(run.records.input_fault);
  const double stopped_after_t = run.summary.stopped_after_t;
  run = {};
  recording.ground_truth.reset();
  releaseFreedMemory();
  writeRunReportOrWarn(out_dir);
  if (fault) {
    std::cout << fmt::format("the recording could not be read after t = {:.6f}: the outputs hold what came before\n",
                             stopped_after_t);
    throw *fault;
  }
}

}  // namespace lvslam::apps
