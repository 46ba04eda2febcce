#pragma once
// The first two keyframes of a map from an accepted two-view initialisation:
// triangulated points, lines matched and triangulated between the two views,
// and a BA with the first keyframe fixed. Plus the conversion of pixel depth
// hints into the initializer's per-keypoint hints.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "lvslam/visual/data/visual_map.h"
#include "lvslam/visual/initialize/two_view_initializer.h"
#include "lvslam/visual/module/line_landmark_creation.h"
#include "lvslam/visual/visual_config.h"

namespace lvslam::visual {

// A depth hint: metric depth z in the camera frame of a pixel of the raw
// (distorted) image, e.g. a LiDAR point projected into it.
struct PixelDepth {
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
  double depth = 0.0;
};

// Per keypoint the nearest hint within radius_px (raw image pixels).
std::vector<DepthHint> depthHintsForKeypoints(const FeatureFrame& frame, const std::vector<PixelDepth>& hints,
                                              double radius_px);

// One frame of the initialisation pair.
struct InitializationView {
  double timestamp = 0.0;
  const FeatureFrame* features = nullptr;
};

struct InitialMap {
  int keyframe1 = -1, keyframe2 = -1;
  std::vector<int> points, lines;
};

// None (and the map left empty) when fewer than `min_points` points survive the BA.
std::optional<InitialMap> buildInitialMap(VisualMap& map, const InitializationView& view1,
                                          const InitializationView& view2, const TwoViewInitialization& init,
                                          const std::vector<TwoViewMatch>& matches,
                                          const PinholeIntrinsics& intrinsics, const VisualConfig& config,
                                          int min_points);

}  // namespace lvslam::visual
