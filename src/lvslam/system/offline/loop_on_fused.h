#pragma once
// Fused mode's loop closure after the run: the odometry of its global pose
// graph is the fused estimator's (refined) trajectory, not the LiDAR's
// alone. Each LiDAR keyframe is carried onto that trajectory through the
// camera frame nearest its time (that frame's T_world_odom = its refined pose
// times its LiDAR odometry pose^-1); the loops the ICP verified are gated
// against those poses afresh, and the graph is solved from them.
#include <optional>

#include "lvslam/core/trajectory.h"
#include "lvslam/loop/loop_closure.h"

namespace lvslam::system {

// `refined`: T_world_camera per frame; `lidar_odometry`: T_odom_camera of
// the LiDAR odometry at (some of) the same time stamps. None when no frame
// has both.
std::optional<loop::LoopClosureResult> loopOnFusedTrajectory(const loop::LoopClosureResult& live,
                                                             const Trajectory& refined,
                                                             const Trajectory& lidar_odometry,
                                                             const loop::LoopClosureConfig& config);

}  // namespace lvslam::system
