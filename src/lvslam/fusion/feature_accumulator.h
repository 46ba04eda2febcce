#pragma once
// Accumulation of LiDAR geometric features over the current and the last
// scans (paper: "the point cloud of the last four frames and the current
// frame"), kept in the world frame and handed out in the camera frame at a
// camera time.
#include <cstdint>
#include <deque>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/fusion/sphere_feature.h"
#include "lvslam/fusion/temporal_alignment.h"

namespace lvslam::fusion {

// A classified LiDAR feature point as the LiDAR subsystem measured it: in the
// LiDAR frame at its own capture time t (raw, or deskewed to t = scan time).
struct TimedFeature {
  Eigen::Vector3d p_lidar = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction_lidar = Eigen::Vector3d::UnitZ();
  FeatureShape shape = FeatureShape::kOther;
  double t = 0.0;
  std::uint64_t id = 0;
};

class FeatureAccumulator {
 public:
  explicit FeatureAccumulator(int max_scans) : max_scans_(max_scans) {}

  // Moves each feature into the world with the pose at its own time (the
  // scan's constant-velocity motion) and drops the oldest scan beyond max.
  void addScan(const std::vector<TimedFeature>& features, const ConstantVelocityMotion& motion);

  // All accumulated features in the camera frame of T_world_camera.
  std::vector<SphereFeature> inCameraFrame(const Eigen::Isometry3d& T_world_camera) const;

  std::size_t scans() const { return scans_.size(); }
  std::size_t size() const;
  void clear() { scans_.clear(); }

 private:
  struct WorldFeature {
    Eigen::Vector3d p_world, direction_world;
    FeatureShape shape;
    std::uint64_t id;
  };
  int max_scans_;
  std::deque<std::vector<WorldFeature>> scans_;
};

}  // namespace lvslam::fusion
