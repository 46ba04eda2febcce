#pragma once
// Offline refinement: what needs the whole run, written apart from the
// online output (trajectory_refined.tum). Fused mode: the online
// estimator's graph over the whole run (kept on disk as the estimator let
// it go; each LiDAR pose as interpolated between the sweeps around it,
// vision as tracked) smoothed (every frame free, every accepted factor, the
// first pose held; solved in overlapping chunks so that the solver's memory
// does not grow with the run). Visual mode and the paper's output:
// the same per-frame output fed with each visual pose placed on its
// keyframe as the keyframe stands at the end (final_visual_poses.h, as
// ORB-SLAM's SaveTrajectoryTUM). LiDAR mode: each frame interpolated
// between the registered sweeps around it (online: the sweep covering it).
// A frame the refinement cannot pose keeps its online pose. Then, in every
// mode with LiDAR loop closure, each frame moved with its keyframe's
// correction (loop_correction.h); in fused mode the loops are gated and the
// keyframe graph solved on the fused trajectory (loop_on_fused.h).
#include <optional>

#include "lvslam/core/trajectory.h"
#include "lvslam/loop/loop_closure.h"
#include "lvslam/system/system_config.h"
#include "lvslam/system/system_pipeline.h"

namespace lvslam::system {

struct Refinement {
  Trajectory trajectory;
  // The loop closure as applied to `trajectory` (fused mode: on the fused
  // poses; otherwise the run's own); none without loop closure.
  std::optional<loop::LoopClosureResult> loop;
};

Refinement refineTrajectory(const PipelineRecords& records, const SystemConfig& config,
                            const Eigen::Isometry3d& T_camera_lidar, const Trajectory& online);

}  // namespace lvslam::system
