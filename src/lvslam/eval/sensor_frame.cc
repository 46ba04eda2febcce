#include "lvslam/eval/sensor_frame.h"

namespace lvslam::eval {

Trajectory inGroundTruthFrame(const Trajectory& estimate, SensorFrame est_frame, SensorFrame gt_frame,
                              const Eigen::Isometry3d& T_camera_lidar) {
  if (est_frame == gt_frame) return estimate;
  // T_world_gt = T_world_est * T_est_gt.
  const Eigen::Isometry3d T_est_gt = est_frame == SensorFrame::kCamera ? T_camera_lidar : T_camera_lidar.inverse();
  Trajectory out = estimate;
  for (StampedPose& pose : out) pose.T_world_frame = pose.T_world_frame * T_est_gt;
  return out;
}

}  // namespace lvslam::eval
