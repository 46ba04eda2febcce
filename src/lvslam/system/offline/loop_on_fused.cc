#include "lvslam/system/offline/loop_on_fused.h"

#include <algorithm>
#include <iterator>

#include "lvslam/system/offline/loop_correction.h"

namespace lvslam::system {

namespace {

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
  const std::vector<OdometryOffset> at_frames = odometryOffsets(refined, lidar_odometry);
  if (at_frames.empty()) return std::nullopt;
  std::vector<Eigen::Isometry3d> keyframes;
  for (std::size_t k = 0; k < live.keyframe_times.size(); ++k)
    keyframes.push_back(nearest(at_frames, live.keyframe_times[k]).T_world_odom * live.T_odom_lidar[k]);
  return loop::regateWithOdometry(live, keyframes, "fused", config);
}

}  // namespace lvslam::system
