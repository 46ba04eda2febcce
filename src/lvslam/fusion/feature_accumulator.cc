#include "lvslam/fusion/feature_accumulator.h"

namespace lvslam::fusion {

void FeatureAccumulator::addScan(const std::vector<TimedFeature>& features, const ConstantVelocityMotion& motion) {
  std::vector<WorldFeature> world;
  world.reserve(features.size());
  for (const TimedFeature& f : features) {
    if (!f.p_lidar.allFinite() || !f.direction_lidar.allFinite()) continue;
    const Eigen::Isometry3d T_world_lidar = motion.poseAt(f.t);
    world.push_back({T_world_lidar * f.p_lidar, T_world_lidar.linear() * f.direction_lidar, f.shape, f.id});
  }
  scans_.push_back(std::move(world));
  while (static_cast<int>(scans_.size()) > max_scans_) scans_.pop_front();
}

std::vector<SphereFeature> FeatureAccumulator::inCameraFrame(const Eigen::Isometry3d& T_world_camera) const {
  const Eigen::Isometry3d T_camera_world = T_world_camera.inverse();
  std::vector<SphereFeature> out;
  out.reserve(size());
  for (const auto& scan : scans_) {
    for (const WorldFeature& f : scan) {
      SphereFeature s;
      s.p_camera = T_camera_world * f.p_world;
      s.direction_camera = T_camera_world.linear() * f.direction_world;
      s.shape = f.shape;
      s.id = f.id;
      out.push_back(s);
    }
  }
  return out;
}

std::size_t FeatureAccumulator::size() const {
  std::size_t n = 0;
  for (const auto& scan : scans_) n += scan.size();
  return n;
}

}  // namespace lvslam::fusion
