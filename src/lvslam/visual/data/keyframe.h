#pragma once
// A keyframe: a frame's features, its pose and which landmark each feature
// observes (-1: none).
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/visual/feature/feature_frame.h"

namespace lvslam::visual {

struct Keyframe {
  int id = -1;
  double timestamp = 0.0;
  Eigen::Isometry3d T_camera_world = Eigen::Isometry3d::Identity();
  FeatureFrame features;
  std::vector<int> point_landmark;  // per keypoint: landmark id or -1
  std::vector<int> line_landmark;   // per line segment: landmark id or -1
};

}  // namespace lvslam::visual
