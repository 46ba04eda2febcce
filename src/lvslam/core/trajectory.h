#pragma once
// A trajectory: poses T_world_frame at increasing time stamps.
#include <vector>

#include <Eigen/Geometry>

namespace lvslam {

struct StampedPose {
  double t = 0.0;
  Eigen::Isometry3d T_world_frame = Eigen::Isometry3d::Identity();
};

using Trajectory = std::vector<StampedPose>;

}  // namespace lvslam
