#pragma once
// First step on a raw scan: drop invalid returns, crop by range, voxel
// downsample (one point kept per voxel).
#include <vector>

#include "lvslam/core/lidar_scan.h"
#include "lvslam/lidar/deskew.h"
#include "lvslam/lidar/lidar_config.h"

namespace lvslam::lidar {

// Non-finite points and points outside [min_range, max_range] are dropped,
// and with ring_neighbour_radius > 0 the returns of surfaces nearly parallel
// to the beam (grazing_returns.h). Times are zero when the scan has none.
std::vector<TimedPoint> cropAndDownsample(const LidarScan& scan, const PreprocessConfig& config,
                                          double ring_neighbour_radius);

// Voxel edge used at this range: voxel_size, or the size that the angle
// voxel_angle_deg spans at the far edge of the point's 5 m range band when larger.
double voxelSizeAt(double range, const PreprocessConfig& config);

// One point per voxel of voxelSizeAt(range): far returns, dense along a ring
// but sparse across rings, are thinned along the ring. Non-finite points and
// points beyond 100 km are dropped (with voxel_angle_deg 0: plain voxelDownsample).
std::vector<TimedPoint> rangeAdaptiveDownsample(const std::vector<TimedPoint>& points, const PreprocessConfig& config);

// Keeps the first point of each voxel of the given size, in input order.
template <typename Point, typename PositionOf>
std::vector<Point> voxelDownsample(const std::vector<Point>& points, double voxel_size, PositionOf position_of);

}  // namespace lvslam::lidar

#include "lvslam/lidar/voxel_downsample_impl.h"
