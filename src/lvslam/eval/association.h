#pragma once
// Time association of a ground-truth and an estimated trajectory: each pose of
// the shorter one takes the nearest stamp of the longer one within max_dt, as
// evo's sync.associate_trajectories does, but no pose is ever used twice.
#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/core/trajectory.h"

namespace lvslam::eval {

// Indices of one associated pair: gt[gt_index] and est[est_index].
struct IndexPair {
  std::size_t gt_index = 0;
  std::size_t est_index = 0;
};

// Pairs in increasing order of both indices. Both trajectories must have
// strictly increasing stamps (throws lvslam::Error otherwise).
std::vector<IndexPair> associateByTime(const Trajectory& gt, const Trajectory& est, double max_dt);

// The poses of associated pairs side by side: gt[k] belongs with est[k].
struct AssociatedPoses {
  std::vector<Eigen::Isometry3d> gt;
  std::vector<Eigen::Isometry3d> est;
};

AssociatedPoses selectPairs(const Trajectory& gt, const Trajectory& est,
                            const std::vector<IndexPair>& pairs);

}  // namespace lvslam::eval
