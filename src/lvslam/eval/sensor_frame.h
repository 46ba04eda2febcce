#pragma once
// Like with like: an estimate and a ground truth of a rig compare only in the
// same sensor frame. World alignment cannot absorb the camera-LiDAR lever
// arm, so an estimate of the camera against a LiDAR ground truth (or the
// reverse) is moved into the ground truth's frame first. `lvslam run`,
// `bench` and `eval` all call this.
#include <Eigen/Geometry>

#include "lvslam/core/trajectory.h"

namespace lvslam::eval {

enum class SensorFrame { kCamera, kLidar };

// The estimate's poses T_world_<est_frame> as T_world_<gt_frame>, through
// T_camera_lidar; unchanged when both frames are the same.
Trajectory inGroundTruthFrame(const Trajectory& estimate, SensorFrame est_frame, SensorFrame gt_frame,
                              const Eigen::Isometry3d& T_camera_lidar);

}  // namespace lvslam::eval
