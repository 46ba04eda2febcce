#include "lvslam/system/lidar_map_export.h"

namespace lvslam::system {

void LidarMapExport::add(const lidar::FeatureFrame& frame) {
  const Eigen::Isometry3f T_world_lidar = frame.T_world_lidar.cast<float>();
  for (const lidar::FeaturePoint& point : frame.points) {
    const Eigen::Vector3f p_world = T_world_lidar * point.p;
    if (!p_world.allFinite()) continue;
    const auto [it, inserted] = occupied_.try_emplace(lidar::voxelOf(p_world, voxel_size_), points_.size());
    if (inserted) points_.push_back({p_world, static_cast<float>(point.cls)});
  }
}

}  // namespace lvslam::system
