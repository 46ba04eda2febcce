#pragma once
// What the sensors are and how they sit on the robot.
#include <optional>

#include <Eigen/Geometry>

#include "lvslam/core/camera.h"

namespace lvslam {

struct Calibration {
  std::optional<PinholeCamera> camera;
  // p_camera = T_camera_lidar * p_lidar
  Eigen::Isometry3d T_camera_lidar = Eigen::Isometry3d::Identity();
};

}  // namespace lvslam
