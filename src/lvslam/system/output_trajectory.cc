#include "lvslam/system/output_trajectory.h"

#include <algorithm>
#include <cmath>

#include "lvslam/core/se3.h"

namespace lvslam::system {

std::optional<Eigen::Isometry3d> OutputTrajectory::lidarIncrement(const FrameEstimates& frame) const {
  if (!frame.T_odom_lidar || !last_T_odom_lidar_) return std::nullopt;
  // Camera motion between the two frames as the LiDAR saw it:
  // T_cam_prev_cam_now = T_camera_lidar * T_lidar_prev_lidar_now * T_lidar_camera.
  return T_lidar_camera_.inverse() * (last_T_odom_lidar_->inverse() * *frame.T_odom_lidar) * T_lidar_camera_;
}

std::map<int, Eigen::Isometry3d> OutputTrajectory::mapPlacements() const {
  std::map<int, Eigen::Isometry3d> placements;
  for (const auto& [id, anchor] : anchors_) placements.emplace(id, anchor.first);
  return placements;
}

// One bounded step of the camera from where the current anchor puts it
// toward where the first anchor does.
void OutputTrajectory::stepTowardFirst(Anchor& anchor, const Eigen::Isometry3d& T_map_camera) const {
  const Eigen::Isometry3d T_now = anchor.current * T_map_camera;
  const Eigen::Isometry3d T_step =
      boundedStep(T_now, anchor.first * T_map_camera, rejoin_.max_m, rejoin_.max_deg * M_PI / 180.0);
  anchor.current = T_step * T_map_camera.inverse();
}

Eigen::Isometry3d OutputTrajectory::add(const FrameEstimates& frame, OutputSource source) {
  const bool first = trajectory_.empty();
  const Eigen::Isometry3d T_prev = first ? Eigen::Isometry3d::Identity() : trajectory_.back().T_world_frame;
  // Where the LiDAR (or, lacking it, standing still) puts this frame.
  Eigen::Isometry3d T_world_camera = T_prev;
  if (const auto inc = lidarIncrement(frame)) T_world_camera = T_prev * *inc;

  if (source == OutputSource::kVisual && frame.T_map_camera) {
    // anchored_map_id_ starts at -1, which no map has: the first visual frame anchors.
    const bool reanchor = anchored_map_id_ != frame.visual_map_id || last_source_ != OutputSource::kVisual;
    if (reanchor) {
      // On the first frame the visual map frame is the world frame.
      const Eigen::Isometry3d T_world_map =
          first ? Eigen::Isometry3d::Identity() : T_world_camera * frame.T_map_camera->inverse();
      const auto known = anchors_.find(frame.visual_map_id);
      if (known == anchors_.end())
        anchors_[frame.visual_map_id] = {T_world_map, T_world_map};
      else
        known->second.current = T_world_map;
      anchored_map_id_ = frame.visual_map_id;
    } else {
      stepTowardFirst(anchors_.at(anchored_map_id_), *frame.T_map_camera);
    }
    T_world_camera = anchors_.at(anchored_map_id_).current * *frame.T_map_camera;
  } else if (first && frame.T_odom_lidar) {
    // LiDAR from the start: the odometry frame, carried to the camera.
    T_world_camera = *frame.T_odom_lidar * T_lidar_camera_;
  }
  if (frame.T_odom_lidar) last_T_odom_lidar_ = frame.T_odom_lidar;
  last_source_ = source;
  trajectory_.push_back({frame.t, T_world_camera});
  return T_world_camera;
}

}  // namespace lvslam::system
