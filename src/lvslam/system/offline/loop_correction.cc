#include "lvslam/system/offline/loop_correction.h"

#include <algorithm>
#include <cmath>

namespace lvslam::system {

namespace {

constexpr double kSameTime = 1e-6;  // seconds

}  // namespace

LoopCorrection::LoopCorrection(const loop::LoopClosureResult& result)
    : LoopCorrection(result.keyframe_times, result.T_odom_lidar, result.T_odom_lidar_corrected) {}

LoopCorrection::LoopCorrection(const std::vector<double>& times, const std::vector<Eigen::Isometry3d>& T_odom_keyframe,
                               const std::vector<Eigen::Isometry3d>& T_corrected_keyframe)
    : times_(times) {
  for (std::size_t k = 0; k < T_odom_keyframe.size() && k < T_corrected_keyframe.size(); ++k)
    corrections_.push_back(T_corrected_keyframe[k] * T_odom_keyframe[k].inverse());
  if (corrections_.empty()) {
    times_ = {0.0};
    corrections_ = {Eigen::Isometry3d::Identity()};
  }
}

const Eigen::Isometry3d& LoopCorrection::atTime(double t) const {
  const auto after = std::upper_bound(times_.begin(), times_.end(), t);
  const auto k = after == times_.begin() ? 0 : static_cast<std::size_t>(after - times_.begin()) - 1;
  return corrections_[k];
}

std::vector<OdometryOffset> odometryOffsets(const Trajectory& refined, const Trajectory& odometry) {
  std::vector<OdometryOffset> offsets;
  std::size_t o = 0;
  for (const StampedPose& pose : refined) {
    while (o < odometry.size() && odometry[o].t < pose.t - kSameTime) ++o;
    if (o < odometry.size() && std::abs(odometry[o].t - pose.t) <= kSameTime)
      offsets.push_back({pose.t, pose.T_world_frame * odometry[o].T_world_frame.inverse()});
  }
  return offsets;
}

Trajectory correctTrajectory(const Trajectory& refined, const Trajectory& odometry, const LoopCorrection& correction) {
  const std::vector<OdometryOffset> offsets = odometryOffsets(refined, odometry);
  Trajectory corrected;
  corrected.reserve(refined.size());
  Eigen::Isometry3d T_world_odom = Eigen::Isometry3d::Identity();
  std::size_t next = 0;
  for (const StampedPose& pose : refined) {
    while (next < offsets.size() && offsets[next].t <= pose.t) T_world_odom = offsets[next++].T_world_odom;
    const Eigen::Isometry3d T_odom_sensor = T_world_odom.inverse() * pose.T_world_frame;
    corrected.push_back({pose.t, T_world_odom * correction.atTime(pose.t) * T_odom_sensor});
  }
  return corrected;
}

std::vector<PlyPoint> correctMap(const std::vector<PlyPoint>& map, const std::vector<std::size_t>& starts,
                                 const LoopCorrection& correction) {
  std::vector<PlyPoint> moved = map;
  for (std::size_t k = 0; k < starts.size() && k < correction.keyframes(); ++k) {
    const std::size_t end = k + 1 < starts.size() ? starts[k + 1] : moved.size();
    const Eigen::Isometry3f D = correction.ofKeyframe(k).cast<float>();
    for (std::size_t i = starts[k]; i < end && i < moved.size(); ++i) moved[i].p = D * moved[i].p;
  }
  return moved;
}

}  // namespace lvslam::system
