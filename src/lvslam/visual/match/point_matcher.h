#pragma once
// ORB keypoint matching (ORB-SLAM's ORBmatcher): between two frames inside a
// search window (map initialisation) and of projected map points against a
// frame (tracking). Best/second-best ratio test, a distance gate, and each
// keypoint used once.
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "lvslam/visual/feature/feature_frame.h"
#include "lvslam/visual/match/feature_grid.h"

namespace lvslam::visual {

struct PointMatcherConfig {
  int max_distance = 50;    // ORB-SLAM TH_LOW (initialisation / tight)
  double ratio = 0.9;       // best < ratio * second best
  bool check_orientation = true;  // keep the dominant rotation (histogram of angle differences)
};

struct PointMatch {
  int index1 = -1, index2 = -1;  // query side, frame side
  int distance = 0;
};

// Matches of frame a's keypoints to frame b's within `window` pixels.
std::vector<PointMatch> matchInWindow(const FeatureFrame& a, const FeatureFrame& b, const FeatureGrid& grid_b,
                                      double window, const PointMatcherConfig& config = {});

// A map point predicted in the frame: pixel, search radius and its descriptor.
struct ProjectedPoint {
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
  double radius = 10.0;
  cv::Mat descriptor;  // 1 x 32 CV_8U
};

// Matches of projected map points (index1) to the frame's keypoints (index2).
std::vector<PointMatch> matchByProjection(const std::vector<ProjectedPoint>& projected, const FeatureFrame& frame,
                                          const FeatureGrid& grid, const PointMatcherConfig& config = {});

}  // namespace lvslam::visual
