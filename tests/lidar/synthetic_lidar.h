#pragma once
// A small ray-casting LiDAR for tests: planes, boxes and vertical poles seen
// by a spinning multi-ring sensor that moves during the sweep.
#include <functional>
#include <optional>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/core/lidar_scan.h"

namespace lvslam::testing {

struct SyntheticScene {
  struct Plane { Eigen::Vector3d n; double d; };           // n . x = d
  struct Box { Eigen::Vector3d min, max; };                 // solid, axis-aligned
  struct Pole { Eigen::Vector2d center; double radius, z0, z1; };
  std::vector<Plane> planes;
  std::vector<Box> boxes;
  std::vector<Pole> poles;

  // Distance along the unit ray to the first surface, if any.
  std::optional<double> cast(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir) const;
};

// A 24 x 14 x 4 m hall with pillars, boxes and a beam: every direction constrained.
SyntheticScene structuredRoom();
// Only a floor: registration cannot see x, y or yaw.
SyntheticScene floorOnly();

struct SyntheticSensor {
  int rings = 32;
  int columns = 720;
  double min_elevation_deg = -20.0, max_elevation_deg = 15.0;
  double period = 0.1;        // seconds per sweep
  double range_noise = 0.0;   // metres, Gaussian
  double max_range = 60.0;
};

using PoseAtTime = std::function<Eigen::Isometry3d(double)>;

// One sweep starting at t0: each column at its own time and pose; points in
// the LiDAR frame at their own time (raw). world_hits (optional) receives the
// exact world points in the same order.
LidarScan castScan(const SyntheticScene& scene, const PoseAtTime& T_world_lidar, double t0,
                   const SyntheticSensor& sensor, std::mt19937* rng = nullptr,
                   std::vector<Eigen::Vector3d>* world_hits = nullptr);

// A smooth drive through structuredRoom(): forward, turning and swaying.
Eigen::Isometry3d drivePose(double t);

}  // namespace lvslam::testing
