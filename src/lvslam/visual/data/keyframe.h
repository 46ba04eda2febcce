#pragma once
// A keyframe: a frame's features, its pose, which landmark each feature
// observes (-1: none) and, with a LiDAR, the measured depth of its keypoints
// and the LiDAR odometry's pose.
#include <optional>
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
  // Per keypoint: LiDAR depth z in this camera frame, NaN where none; empty
  // when no depths were given (VisualMap::setKeypointDepths).
  std::vector<double> keypoint_depth;
  // The LiDAR odometry's camera pose at this keyframe's time, when the
  // running system gave one (VisualMap::setOdometryPose).
  std::optional<Eigen::Isometry3d> T_odom_camera;
};

}  // namespace lvslam::visual
