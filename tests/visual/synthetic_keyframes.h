#pragma once
// Keyframes observing a synthetic scene's points exactly, for the tests of
// the map modules (triangulation, merging, culling, local mapping).
#include <algorithm>
#include <vector>

#include <opencv2/core.hpp>

#include "lvslam/visual/data/keyframe.h"
#include "visual/synthetic_scene.h"

namespace lvslam::visual::testing {

// A keyframe at T_camera_world with one keypoint (octave 0, exact pixels) per
// visible scene point, whose descriptor is the point's row of `descriptors`
// (the same in every keyframe); point_of_keypoint receives the scene point
// of each keypoint.
inline Keyframe observePoints(const SyntheticScene& scene, const Eigen::Isometry3d& T_camera_world,
                              const cv::Mat& descriptors, std::vector<int>& point_of_keypoint) {
  Keyframe kf;
  kf.T_camera_world = T_camera_world;
  kf.features.width = scene.width;
  kf.features.height = scene.height;
  kf.features.pyramid = {{1.0, 1.2}, {1.0, 1.0 / 1.44}};
  point_of_keypoint.clear();
  for (size_t i = 0; i < scene.points.size(); ++i) {
    const Eigen::Vector3d px = scene.project(kf.T_camera_world, scene.points[i]);
    if (!scene.visible(px)) continue;
    cv::KeyPoint kp(static_cast<float>(px.x()), static_cast<float>(px.y()), 31.0f);
    kp.octave = 0;
    kf.features.keypoints.push_back(kp);
    kf.features.points.push_back(px.head<2>());
    kf.features.descriptors.push_back(descriptors.row(static_cast<int>(i)));
    point_of_keypoint.push_back(static_cast<int>(i));
  }
  return kf;
}

// The keypoint observing scene point `point` (observePoints' point_of_keypoint), -1 if none.
inline int keypointOf(const std::vector<int>& point_of_keypoint, int point) {
  const auto it = std::find(point_of_keypoint.begin(), point_of_keypoint.end(), point);
  return it == point_of_keypoint.end() ? -1 : static_cast<int>(it - point_of_keypoint.begin());
}

// Distinct random ORB descriptors, one row per scene point.
inline cv::Mat randomDescriptors(int rows) {
  cv::Mat d(rows, 32, CV_8U);
  cv::randu(d, 0, 256);
  return d;
}

}  // namespace lvslam::visual::testing
