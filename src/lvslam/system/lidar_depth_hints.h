#pragma once
// LiDAR depth for image points (paper: the metric start of the visual
// subsystem): raw LiDAR points measured close to the image time, projected
// through T_camera_lidar. Only points within max_dt of the image are used:
// the robot moves during a sweep, and without deskew the hint error grows
// with the time between the point and the image. Given the camera's own
// motion, points are first moved to the camera pose at the image time, so a
// whole sweep can be used.
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/core/calibration.h"
#include "lvslam/core/lidar_scan.h"
#include "lvslam/visual/geometry/surface_depth.h"

namespace lvslam::system {

// The camera at another time, seen from the camera at the image time (e.g.
// the previous tracked frame); constant velocity in between and beyond.
struct CameraMotion {
  double t_other = 0.0;
  Eigen::Isometry3d T_image_other = Eigen::Isometry3d::Identity();
};

// `scans` are the latest scans (those that bracket the image time); points
// closer than min_depth in front of the camera are skipped.
std::vector<visual::PixelDepth> lidarDepthHints(const std::vector<std::shared_ptr<const LidarScan>>& scans,
                                                double t_image, const Calibration& calibration, double max_dt,
                                                const std::optional<CameraMotion>& motion = std::nullopt,
                                                double min_depth = 0.3);

}  // namespace lvslam::system
