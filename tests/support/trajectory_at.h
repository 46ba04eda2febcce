#pragma once
// A trajectory's pose at any time: interpolated between the poses around
// it, held at the ends (ground truth at an estimate's time stamps).
#include <algorithm>

#include "lvslam/core/se3.h"
#include "lvslam/core/trajectory.h"

namespace lvslam::testing {

inline Eigen::Isometry3d poseAt(const Trajectory& trajectory, double t) {
  const auto after = std::lower_bound(trajectory.begin(), trajectory.end(), t,
                                      [](const StampedPose& p, double s) { return p.t < s; });
  if (after == trajectory.begin()) return after->T_world_frame;
  if (after == trajectory.end()) return trajectory.back().T_world_frame;
  const auto before = after - 1;
  return interpolateAtTime(t, before->t, before->T_world_frame, after->t, after->T_world_frame);
}

}  // namespace lvslam::testing
