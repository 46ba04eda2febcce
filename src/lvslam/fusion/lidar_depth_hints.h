#pragma once
// LiDAR depth for image points (paper: the metric start of the visual
// subsystem): raw LiDAR points measured close to the image time, projected
// through T_camera_lidar. Only points within max_dt of the image are used:
// the robot moves during a sweep, and without deskew the hint error grows
// with the time between the point and the image.
#include <memory>
#include <vector>

#include "lvslam/core/calibration.h"
#include "lvslam/core/lidar_scan.h"
#include "lvslam/visual/tracking/map_initialization.h"

namespace lvslam::fusion {

// `scans` are the latest scans (those that bracket the image time); points
// closer than min_depth in front of the camera are skipped.
std::vector<visual::PixelDepth> lidarDepthHints(const std::vector<std::shared_ptr<const LidarScan>>& scans,
                                                double t_image, const Calibration& calibration, double max_dt,
                                                double min_depth = 0.3);

}  // namespace lvslam::fusion
