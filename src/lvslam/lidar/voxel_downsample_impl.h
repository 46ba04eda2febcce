#pragma once
// Template body of voxelDownsample (preprocess.h).
#include <tsl/robin_set.h>

#include "lvslam/lidar/voxel_key.h"

namespace lvslam::lidar {

template <typename Point, typename PositionOf>
std::vector<Point> voxelDownsample(const std::vector<Point>& points, double voxel_size, PositionOf position_of) {
  tsl::robin_set<VoxelKey, VoxelKeyHash> occupied;
  occupied.reserve(points.size());
  std::vector<Point> kept;
  kept.reserve(points.size() / 2);
  for (const Point& point : points) {
    if (occupied.insert(voxelOf(position_of(point), voxel_size)).second) kept.push_back(point);
  }
  return kept;
}

}  // namespace lvslam::lidar
