#pragma once
// The LiDAR map a user opens (map.ply): every registered frame's feature
// points in the odometry's world frame, one point per voxel (the first one
// seen), so memory grows with the explored space, not with time.
#include <vector>

#include <tsl/robin_map.h>

#include "lvslam/io/ply_writer.h"
#include "lvslam/lidar/feature_point.h"
#include "lvslam/lidar/voxel_key.h"

namespace lvslam::system {

class LidarMapExport {
 public:
  explicit LidarMapExport(double voxel_size) : voxel_size_(voxel_size) {}

  // A registered frame; the PLY intensity is the feature class (0 ground ..
  // 5 vertex) so viewers can colour by class.
  void add(const lidar::FeatureFrame& frame);

  const std::vector<PlyPoint>& points() const { return points_; }  // in insertion order

 private:
  double voxel_size_;
  tsl::robin_map<lidar::VoxelKey, std::size_t, lidar::VoxelKeyHash> occupied_;
  std::vector<PlyPoint> points_;
};

}  // namespace lvslam::system
