#pragma once
// What VisualSlam::track() reports for one frame.
#include <optional>

#include <Eigen/Geometry>

#include "lvslam/core/se3.h"
#include "lvslam/core/trajectory.h"
#include "lvslam/visual/tracking/frame_tracker.h"

namespace lvslam::visual {

enum class TrackingState { kInitializing, kTracking, kLost };
const char* trackingStateName(TrackingState state);

// Replay data: what the after-run refinement needs to place the frame again
// on the map as it stands at the end; the online output does not use it.
struct VisualReplayData {
  // The keyframe the frame was tracked against and the frame's pose relative
  // to it then (T_keyframe_camera), to place the frame on the map's final
  // keyframe poses (as ORB-SLAM's SaveTrajectoryTUM); -1 when none.
  int reference_keyframe = -1;
  Eigen::Isometry3d T_keyframe_camera = Eigen::Isometry3d::Identity();
  // The inliers the tracked pose rests on, to optimise it again against the
  // map's final landmarks (VisualSlam::relocateInFinalMap); empty when the
  // pose did not come from tracking.
  TrackedObservations observations;
};

// What the detection module reads of a frame (its paper's health checks).
struct FrameHealth {
  int tracked_points = 0, tracked_lines = 0;
  double inlier_ratio = 0.0;  // inliers / matches of the last pose optimisation
  double brightness = 0.0, contrast = 0.0;
  int keypoints = 0, segments = 0;
};

// What the online estimator (system/online/fused_estimator.h) reads besides
// the pose.
struct VisualFusionInfo {
  // The tracker's information on the pose (PoseOptimizationResult::information,
  // at 1 px per ORB level 0; none when the pose did not come from tracking).
  std::optional<Matrix6d> pose_information;
  // The map's alignment with the LiDAR odometry (VisualMap::T_world_odom).
  std::optional<Eigen::Isometry3d> T_world_odom;
  // When the landmarks the pose rests on were mapped (medianFirstSeen of its
  // inlier points); with a pose_information only.
  std::optional<double> anchor_time;
  // The map was pulled onto the LiDAR odometry in this frame
  // (config.modules.map_correction): earlier poses of this map are, in the
  // corrected map, T_new_old * T_world_camera (the newest keyframe's move).
  std::optional<Eigen::Isometry3d> T_new_old;
};

// One frame: its pose (the fields below), its health, what fusion reads, and
// the replay data the after-run refinement may ask for.
struct VisualFrameResult {
  double timestamp = 0.0;
  TrackingState state = TrackingState::kInitializing;
  bool pose_valid = false;  // tracked (or initialised) in this frame
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();  // world = the map's frame
  int map_id = 0;
  bool keyframe = false;
  bool metric = false;  // the map's scale came from depth hints
  // The map was initialised in this frame: its first view, at an earlier time
  // (keyframe initial_reference_keyframe).
  std::optional<StampedPose> initial_reference;
  int initial_reference_keyframe = -1;
  FrameHealth health;
  VisualFusionInfo fusion;
  // For the after-run refinement only (system/final_visual_poses.h).
  VisualReplayData replay;
};

}  // namespace lvslam::visual
