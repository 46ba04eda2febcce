#pragma once
// Ground points and their normals from a 2D grid of lowest points with a
// plane fitted per cell (MULLS's grid-based ground filter, simplified).
#include <vector>

#include <Eigen/Core>

#include "lvslam/lidar/deskew.h"
#include "lvslam/lidar/lidar_config.h"

namespace lvslam::lidar {

struct GroundSegmentation {
  std::vector<bool> is_ground;              // per input point
  std::vector<Eigen::Vector3f> normal;      // per input point; meaningful where is_ground, pointing up
};

// Points in the LiDAR frame, z up (the sensor is mounted roughly level).
GroundSegmentation segmentGround(const std::vector<TimedPoint>& points, const GroundConfig& config);

}  // namespace lvslam::lidar
