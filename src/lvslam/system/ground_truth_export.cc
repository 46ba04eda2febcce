#include "lvslam/system/ground_truth_export.h"

namespace lvslam::system {

std::optional<Trajectory> groundTruthInOutputFrame(const Recording& recording, const SystemOutput& output) {
  if (!recording.ground_truth) return std::nullopt;
  const bool gt_is_camera = recording.ground_truth_frame == GroundTruthFrame::kCamera;
  const Eigen::Isometry3d T_camera_lidar = recording.source->calibration().T_camera_lidar;
  Trajectory gt = *recording.ground_truth;
  // T_world_camera = T_world_lidar T_lidar_camera, and the other way round.
  if (output.trajectory_is_camera && !gt_is_camera)
    for (StampedPose& pose : gt) pose.T_world_frame = pose.T_world_frame * T_camera_lidar.inverse();
  if (!output.trajectory_is_camera && gt_is_camera)
    for (StampedPose& pose : gt) pose.T_world_frame = pose.T_world_frame * T_camera_lidar;
  return gt;
}

}  // namespace lvslam::system
