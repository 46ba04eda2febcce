#pragma once
// What loop closure changes after the run: each keyframe's correction
// D_k = T_corrected_k T_odometry_k^-1 (odometry frame), carried by every
// frame from its keyframe on until the next keyframe (its pose relative
// to that keyframe is kept), and by every map point added from its scan on.
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/core/trajectory.h"
#include "lvslam/io/ply_writer.h"
#include "lvslam/loop/loop_closure.h"

namespace lvslam::system {

class LoopCorrection {
 public:
  explicit LoopCorrection(const loop::LoopClosureResult& result);
  // From each keyframe's pose in another odometry (whose frame the points
  // or poses to move are in) to its corrected pose.
  LoopCorrection(const std::vector<double>& times, const std::vector<Eigen::Isometry3d>& T_odom_keyframe,
                 const std::vector<Eigen::Isometry3d>& T_corrected_keyframe);

  // Of the last keyframe at or before t (the first keyframe's before it).
  const Eigen::Isometry3d& atTime(double t) const;
  const Eigen::Isometry3d& ofKeyframe(std::size_t k) const { return corrections_[k]; }
  std::size_t keyframes() const { return corrections_.size(); }

 private:
  std::vector<double> times_;
  std::vector<Eigen::Isometry3d> corrections_;
};

// T_world_odom = T_world_sensor T_odom_sensor^-1 at each time stamp of
// `refined` that `odometry` (the same sensor's odometry) also has, within a
// microsecond; in time order.
struct OdometryOffset {
  double t = 0.0;
  Eigen::Isometry3d T_world_odom = Eigen::Isometry3d::Identity();
};
std::vector<OdometryOffset> odometryOffsets(const Trajectory& refined, const Trajectory& odometry);

// Each pose of `refined` moved by the correction at its time, applied in the
// odometry frame: T' = T_world_odom D T_odom_sensor, with T_world_odom =
// T T_odom_sensor^-1 from `odometry` (the same sensor's odometry pose at
// the same time stamps; where it has none, the last such offset).
Trajectory correctTrajectory(const Trajectory& refined, const Trajectory& odometry, const LoopCorrection& correction);

// The exported LiDAR map (odometry frame) moved point by point with the
// keyframe whose scan it was added from on; `starts` from LidarWorker::mapKeyframeStarts().
std::vector<PlyPoint> correctMap(const std::vector<PlyPoint>& map, const std::vector<std::size_t>& starts,
                                 const LoopCorrection& correction);

}  // namespace lvslam::system
