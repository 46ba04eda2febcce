#include "live_map.h"

#include <cmath>

namespace lvslam::ros_node {

namespace {

constexpr double kRadPerDeg = M_PI / 180.0;

// 21 bits per axis: +-104 km at 10 cm voxels.
std::int64_t packVoxel(const Eigen::Vector3f& p, double voxel_m) {
  const auto cell = [&](float v) {
    return static_cast<std::int64_t>(std::floor(static_cast<double>(v) / voxel_m)) & ((1 << 21) - 1);
  };
  return (cell(p.x()) << 42) | (cell(p.y()) << 21) | cell(p.z());
}

}  // namespace

LiveMap::LiveMap(const LiveMapOptions& options, const Eigen::Isometry3d& T_camera_lidar)
    : options_(options), T_camera_lidar_(T_camera_lidar) {}

std::int64_t LiveMap::key(const Eigen::Vector3f& p) const { return packVoxel(p, options_.voxel_m); }

void LiveMap::addScan(const LidarScan& scan) {
  Pending sweep{scan.timestamp, {}};
  std::unordered_set<std::int64_t> seen;
  for (const LidarPoint& p : scan.points)
    if (seen.insert(key(p.p)).second) sweep.points.push_back(p.p);
  std::lock_guard lock(mutex_);
  pending_.push_back(std::move(sweep));
  while (pending_.size() > options_.max_pending) pending_.pop_front();
}

void LiveMap::addPose(double t, const Eigen::Isometry3d& T_world_camera) {
  std::lock_guard lock(mutex_);
  while (!pending_.empty() && pending_.front().t <= t) {
    const Eigen::Isometry3d T_world_lidar = T_world_camera * T_camera_lidar_;
    const Eigen::Isometry3d step = T_world_last_.inverse() * T_world_lidar;
    const bool moved = !have_last_ || step.translation().norm() >= options_.min_step_m ||
                       Eigen::AngleAxisd(step.rotation()).angle() >= options_.min_turn_deg * kRadPerDeg;
    if (moved && points_.size() < options_.max_points) {
      insert(pending_.front(), T_world_lidar);
      T_world_last_ = T_world_lidar;
      have_last_ = true;
    }
    pending_.pop_front();
  }
}

void LiveMap::insert(const Pending& sweep, const Eigen::Isometry3d& T_world_lidar) {
  const Eigen::Isometry3f T = T_world_lidar.cast<float>();
  for (const Eigen::Vector3f& p_lidar : sweep.points) {
    const Eigen::Vector3f p = T * p_lidar;
    if (voxels_.insert(key(p)).second) points_.push_back(p);
  }
}

std::vector<Eigen::Vector3f> LiveMap::points() const {
  std::lock_guard lock(mutex_);
  return points_;
}

std::size_t LiveMap::size() const {
  std::lock_guard lock(mutex_);
  return points_.size();
}

}  // namespace lvslam::ros_node
