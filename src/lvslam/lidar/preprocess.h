#pragma once
// First step on a raw scan: drop invalid returns, crop by range, voxel
// downsample (one point kept per voxel).
#include <vector>

#include "lvslam/core/lidar_scan.h"
#include "lvslam/lidar/deskew.h"
#include "lvslam/lidar/lidar_config.h"

namespace lvslam::lidar {

// Non-finite points and points outside [min_range, max_range] are dropped.
// Times are zero when the scan has none.
std::vector<TimedPoint> cropAndDownsample(const LidarScan& scan, const PreprocessConfig& config);

// Keeps the first point of each voxel of the given size, in input order.
template <typename Point, typename PositionOf>
std::vector<Point> voxelDownsample(const std::vector<Point>& points, double voxel_size, PositionOf position_of);

}  // namespace lvslam::lidar

#include "lvslam/lidar/voxel_downsample_impl.h"
