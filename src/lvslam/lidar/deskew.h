#pragma once
// Motion compensation under constant body velocity over a sweep (the paper's
// temporal alignment: constant angular and linear velocity over a short period).
#include <vector>

#include <Eigen/Core>

#include "lvslam/core/se3.h"

namespace lvslam::lidar {

// A point with its capture time relative to the frame's reference time.
struct TimedPoint {
  Eigen::Vector3f p = Eigen::Vector3f::Zero();
  float time = 0.0f;
  int ring = -1;  // laser index, -1 when the scan has none
};

// velocity: body twist per second (rho, phi), so that
// T_world_lidar(t_ref + dt) = T_world_lidar(t_ref) * expSE3(velocity * dt).
// Returns T_ref_at: the LiDAR pose at t_ref + dt seen from the pose at t_ref.
Eigen::Isometry3d motionOver(const Vector6d& velocity, double dt);

// Moves every point from the LiDAR frame at its own capture time into the
// LiDAR frame at the reference time (p_ref = T_ref_at(time) * p).
void deskewToReference(std::vector<TimedPoint>& points, const Vector6d& velocity);

// Body velocity that carries T_world_prev at t_prev to T_world_cur at t_cur.
Vector6d velocityBetween(const Eigen::Isometry3d& T_world_prev, double t_prev, const Eigen::Isometry3d& T_world_cur,
                         double t_cur);

}  // namespace lvslam::lidar
