#pragma once
// The LiDAR map shown while the node runs: sweeps placed by the online
// output's pose nearest after their stamp (T_world_camera * T_camera_lidar),
// one point per voxel, a sweep added only once the robot has moved. For
// display only (the sweep is not deskewed); on shutdown map.ply is the
// system's own map, as `lvslam run` writes it. Knows nothing of ROS.
#include <cstdint>
#include <deque>
#include <mutex>
#include <unordered_set>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/core/lidar_scan.h"

namespace lvslam::ros_node {

struct LiveMapOptions {
  double voxel_m = 0.2;
  double min_step_m = 0.5, min_turn_deg = 10.0;  // motion before the next sweep is added
  std::size_t max_points = 2'000'000;            // the map stops growing here
  std::size_t max_pending = 20;                  // sweeps waiting for a pose
};

class LiveMap {
 public:
  LiveMap(const LiveMapOptions& options, const Eigen::Isometry3d& T_camera_lidar);

  void addScan(const LidarScan& scan);  // thinned to one point per voxel in the LiDAR frame first
  void addPose(double t, const Eigen::Isometry3d& T_world_camera);
  std::vector<Eigen::Vector3f> points() const;  // world frame
  std::size_t size() const;

 private:
  struct Pending {
    double t;
    std::vector<Eigen::Vector3f> points;
  };
  void insert(const Pending& sweep, const Eigen::Isometry3d& T_world_lidar);
  std::int64_t key(const Eigen::Vector3f& p) const;

  LiveMapOptions options_;
  Eigen::Isometry3d T_camera_lidar_;
  mutable std::mutex mutex_;
  std::deque<Pending> pending_;
  std::unordered_set<std::int64_t> voxels_;  // of `points_`
  std::vector<Eigen::Vector3f> points_;
  bool have_last_ = false;
  Eigen::Isometry3d T_world_last_ = Eigen::Isometry3d::Identity();
};

}  // namespace lvslam::ros_node
