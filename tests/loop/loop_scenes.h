#pragma once
// Scans of the loop tests: the synthetic hall of tests/lidar and a second,
// different place, seen by a static sensor and classified by the LiDAR
// subsystem as a keyframe would be.
#include <vector>

#include <Eigen/Geometry>

#include "lidar/synthetic_lidar.h"
#include "lvslam/lidar/feature_point.h"
#include "lvslam/sim/lidar_simulator.h"
#include "lvslam/sim/scenario.h"

namespace lvslam::testing {

// An L-shaped 16 x 10 m store room with shelves and columns, nothing like structuredRoom().
SyntheticScene storeRoom();

// The LiDAR features of a static scan from T_world_lidar (LiDAR frame).
std::vector<lidar::FeaturePoint> keyframeFeatures(const SyntheticScene& scene, const Eigen::Isometry3d& T_world_lidar);

// The LiDAR subsystem's keyframe features of the simulator's sweep that
// starts at t, deskewed with the true motion over it.
std::vector<lidar::FeaturePoint> keyframeFeatures(const sim::Scenario& scenario, const sim::LidarSimulator& lidar,
                                                  double t);


}  // namespace lvslam::testing
