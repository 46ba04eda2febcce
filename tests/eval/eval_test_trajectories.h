#pragma once
// Trajectories with known geometry for the eval tests.
#include <cmath>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/core/se3.h"
#include "lvslam/core/trajectory.h"

namespace lvslam::eval::testing {

// A climbing spiral with turning orientation: positions span 3D, so
// alignment is well posed. Stamped 0.1 s apart.
inline Trajectory makeSpiral(int count) {
  Trajectory traj;
  for (int k = 0; k < count; ++k) {
    const double a = 0.1 * k;
    const Eigen::Vector3d p(10.0 * std::cos(a), 10.0 * std::sin(a), 0.3 * k);
    traj.push_back({0.1 * k, makePose(expSO3(Eigen::Vector3d(0.01 * k, 0.0, a)), p)});
  }
  return traj;
}

// Poses along +x with identity orientation at the given positions.
inline std::vector<double> evenlySpaced(int count, double step) {
  std::vector<double> xs;
  for (int k = 0; k < count; ++k) xs.push_back(step * k);
  return xs;
}

inline std::vector<Eigen::Isometry3d> posesAlongX(const std::vector<double>& xs) {
  std::vector<Eigen::Isometry3d> poses;
  for (const double x : xs) poses.push_back(makePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(x, 0, 0)));
  return poses;
}

inline std::vector<Eigen::Isometry3d> posesOf(const Trajectory& traj) {
  std::vector<Eigen::Isometry3d> poses;
  for (const StampedPose& p : traj) poses.push_back(p.T_world_frame);
  return poses;
}

}  // namespace lvslam::eval::testing
