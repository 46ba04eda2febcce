#include "lvslam/eval/sensor_frame.h"

namespace lvslam::eval {

Trajectory inSensorFrame(const Trajectory& trajectory, SensorFrame from, SensorFrame to,
                         const Eigen::Isometry3d& T_camera_lidar) {
  if (from == to) return trajectory;
  // T_world_to = T_world_from * T_from_to.
  const Eigen::Isometry3d T_from_to = from == SensorFrame::kCamera ? T_camera_lidar : T_camera_lidar.inverse();
  Trajectory out = trajectory;
  for (StampedPose& pose : out) pose.T_world_frame = pose.T_world_frame * T_from_to;
  return out;
}

}  // namespace lvslam::eval
