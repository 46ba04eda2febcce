#pragma once
// What the sensors are and how they sit on the robot.
#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "lvslam/core/camera.h"

namespace lvslam {

struct Calibration {
  std::optional<PinholeCamera> camera;
  // p_camera = T_camera_lidar * p_lidar
  Eigen::Isometry3d T_camera_lidar = Eigen::Isometry3d::Identity();
  // Where T_camera_lidar was read, for warnings about it ("FILE: key '...'");
  // empty when it came from no file (the simulator, a test).
  std::string T_camera_lidar_source;
};

}  // namespace lvslam
