#include "lvslam/system/ground_truth_export.h"

#include "lvslam/eval/sensor_frame.h"

namespace lvslam::system {

std::optional<Trajectory> groundTruthInOutputFrame(const Recording& recording, const SystemOutput& output) {
  if (!recording.ground_truth) return std::nullopt;
  const bool gt_is_camera = recording.ground_truth_frame == GroundTruthFrame::kCamera;
  const Eigen::Isometry3d T_camera_lidar = recording.source->calibration().T_camera_lidar;
  return eval::inSensorFrame(*recording.ground_truth, eval::sensorFrameOf(gt_is_camera),
                             eval::sensorFrameOf(output.trajectory_is_camera), T_camera_lidar);
}

}  // namespace lvslam::system
