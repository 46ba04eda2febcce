#pragma once
// The camera-LiDAR rig of the fusion unit tests: a 640 x 480 camera (f = 400
// px) looking along the LiDAR's x axis (camera z forward, x right, y down;
// LiDAR x forward, y left, z up), 10 cm below it.
#include <Eigen/Geometry>

#include "lvslam/core/camera.h"
#include "lvslam/core/se3.h"

namespace lvslam::fusion::testing {

inline Eigen::Isometry3d cameraFromLidar() {
  Eigen::Matrix3d R_lidar_camera;
  R_lidar_camera << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  return makePose(R_lidar_camera, Eigen::Vector3d(0.1, 0.0, -0.1)).inverse();
}

inline PinholeCamera testCamera() { return PinholeCamera(640, 480, 400.0, 400.0, 320.0, 240.0); }

}  // namespace lvslam::fusion::testing
