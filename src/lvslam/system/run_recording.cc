#include "lvslam/system/run_recording.h"

#include <chrono>

namespace lvslam::system {

namespace {

Trajectory transformed(const Trajectory& trajectory, const Eigen::Isometry3d& T_frame_other) {
  Trajectory out = trajectory;
  for (StampedPose& pose : out) pose.T_world_frame = pose.T_world_frame * T_frame_other;
  return out;
}

}  // namespace

std::optional<eval::EvalResult> evaluateOutput(const Recording& recording, const SystemOutput& output,
                                               const Trajectory& trajectory) {
  if (!recording.ground_truth || trajectory.size() < eval::kMinAssociatedPairs) return std::nullopt;
  const bool gt_is_camera = recording.ground_truth_frame == GroundTruthFrame::kCamera;
  const Eigen::Isometry3d T_camera_lidar = recording.source->calibration().T_camera_lidar;
  // Compare like with like: the estimate in the frame the ground truth gives.
  Trajectory estimate = trajectory;
  if (output.trajectory_is_camera && !gt_is_camera) estimate = transformed(estimate, T_camera_lidar);
  if (!output.trajectory_is_camera && gt_is_camera) estimate = transformed(estimate, T_camera_lidar.inverse());
  eval::EvalOptions options;
  options.alignment = output.metric ? eval::Alignment::kSE3 : eval::Alignment::kSim3;
  options.gt_name = recording.ground_truth_path;
  options.est_name = gt_is_camera ? "estimate (camera frame)" : "estimate (lidar frame)";
  return eval::evaluate(*recording.ground_truth, estimate, options);
}

RunResult runRecording(Recording& recording, const SystemConfig& config, const ProgressCallback& progress) {
  RunResult run;
  const auto start = std::chrono::steady_clock::now();
  run.records = runPipeline(*recording.source, config, progress);
  run.output = assembleOutput(run.records, config, recording.source->calibration().T_camera_lidar);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.summary = summarize(run.records, run.output, config.mode, wall);
  run.accuracy = evaluateOutput(recording, run.output, run.output.trajectory);
  run.accuracy_refined = evaluateOutput(recording, run.output, run.output.trajectory_refined);
  return run;
}

}  // namespace lvslam::system
