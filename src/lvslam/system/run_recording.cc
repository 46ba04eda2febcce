#include "lvslam/system/run_recording.h"

#include <chrono>

#include "lvslam/eval/sensor_frame.h"

namespace lvslam::system {

std::optional<eval::EvalResult> evaluateOutput(const Recording& recording, const SystemOutput& output,
                                               const Trajectory& trajectory) {
  if (!recording.ground_truth || trajectory.size() < eval::kMinAssociatedPairs) return std::nullopt;
  const bool gt_is_camera = recording.ground_truth_frame == GroundTruthFrame::kCamera;
  const Eigen::Isometry3d T_camera_lidar = recording.source->calibration().T_camera_lidar;
  const Trajectory estimate = eval::inSensorFrame(trajectory, eval::sensorFrameOf(output.trajectory_is_camera),
                                                  eval::sensorFrameOf(gt_is_camera), T_camera_lidar);
  eval::EvalOptions options;
  options.alignment = output.metric ? eval::Alignment::kSE3 : eval::Alignment::kSim3;
  options.gt_name = recording.ground_truth_path;
  options.est_name = gt_is_camera ? "estimate (camera frame)" : "estimate (lidar frame)";
  return eval::evaluate(*recording.ground_truth, estimate, options);
}

RunResult runRecording(Recording& recording, const SystemConfig& config, const ProgressCallback& progress,
                       const FrameOutputCallback& on_frame) {
  RunResult run;
  const auto start = std::chrono::steady_clock::now();
  run.records = runPipeline(*recording.source, config, progress, on_frame);
  run.output = assembleOutput(run.records, config, recording.source->calibration().T_camera_lidar);
  const auto end = std::chrono::steady_clock::now();
  run.summary = summarize(run.records, run.output, config.mode, std::chrono::duration<double>(run.records.online_end - start).count(),
                          std::chrono::duration<double>(end - start).count());
  run.accuracy = evaluateOutput(recording, run.output, run.output.trajectory);
  run.accuracy_refined = evaluateOutput(recording, run.output, run.output.trajectory_refined);
  return run;
}

}  // namespace lvslam::system
