#pragma once
// Like with like: an estimate and a ground truth of a rig compare only in the
// same sensor frame. World alignment cannot absorb the camera-LiDAR lever
// arm, so an estimate of the camera against a LiDAR ground truth (or the
// reverse) is moved into the ground truth's frame first (or the ground truth
// into the estimate's, for export). `lvslam run`,
// `bench` and `eval` all call this.
#include <Eigen/Geometry>

#include "lvslam/core/trajectory.h"

namespace lvslam::eval {

enum class SensorFrame { kCamera, kLidar };

inline SensorFrame sensorFrameOf(bool is_camera) { return is_camera ? SensorFrame::kCamera : SensorFrame::kLidar; }

// Poses T_world_<from> as T_world_<to>, through T_camera_lidar; unchanged
// when both frames are the same.
Trajectory inSensorFrame(const Trajectory& trajectory, SensorFrame from, SensorFrame to,
                         const Eigen::Isometry3d& T_camera_lidar);

}  // namespace lvslam::eval
