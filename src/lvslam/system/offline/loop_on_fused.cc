#include "lvslam/system/offline/loop_on_fused.h"

#include <algorithm>
#include <cmath>

namespace lvslam::system {

namespace {

constexpr double kSameTime = 1e-6;  // seconds

struct OdometryOffset {
  double t = 0.0;
  Eigen::Isometry3d T_world_odom = Eigen::Isometry3d::Identity();
};

// T_world_odom at every frame both trajectories pose.
std::vector<OdometryOffset> offsets(const Trajectory& refined, const Trajectory& lidar_odometry) {
  std::vector<OdometryOffset> out;
  std::size_t o = 0;
  for (const StampedPose& pose : refined) {
    while (o < lidar_odometry.size() && lidar_odometry[o].t < pose.t - kSameTime) ++o;
    if (o < lidar_odometry.size() && std::abs(lidar_odometry[o].t - pose.t) <= kSameTime)
      out.push_back({pose.t, pose.T_world_frame * lidar_odometry[o].T_world_frame.inverse()});
  }
  return out;
}

const OdometryOffset& nearest(const std::vector<OdometryOffset>& offsets, double t) {
  const auto after = std::lower_bound(offsets.begin(), offsets.end(), t,
                                      [](const OdometryOffset& o, double time) { return o.t < time; });
  if (after == offsets.begin()) return *after;
  if (after == offsets.end()) return offsets.back();
  return after->t - t < t - std::prev(after)->t ? *after : *std::prev(after);
}

}  // namespace

std::optional<loop::LoopClosureResult> loopOnFusedTrajectory(const loop::LoopClosureResult& live,
                                                             const Trajectory& refined,
                                                             const Trajectory& lidar_odometry,
                                                             const loop::LoopClosureConfig& config) {
  const std::vector<OdometryOffset> at_frames = offsets(refined, lidar_odometry);
  if (at_frames.empty()) return std::nullopt;
  std::vector<Eigen::Isometry3d> keyframes;
  for (std::size_t k = 0; k < live.keyframe_times.size(); ++k)
    keyframes.push_back(nearest(at_frames, live.keyframe_times[k]).T_world_odom * live.T_odom_lidar[k]);
  return loop::regateWithOdometry(live, keyframes, "fused", config);
}

}  // namespace lvslam::system
