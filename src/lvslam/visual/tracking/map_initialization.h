#pragma once
// A map's first keyframes: from one view whose keypoints have metric depth
// (LiDAR), or from an accepted two-view initialisation (triangulated points,
// lines matched and triangulated between the two views, and a BA with the
// first keyframe fixed).
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "lvslam/visual/data/visual_map.h"
#include "lvslam/visual/initialize/two_view_initializer.h"
#include "lvslam/visual/module/line_landmark_creation.h"
#include "lvslam/visual/visual_config.h"

namespace lvslam::visual {

// One frame of the initialisation pair.
struct InitializationView {
  double timestamp = 0.0;
  const FeatureFrame* features = nullptr;
};

struct InitialMap {
  int keyframe1 = -1, keyframe2 = -1;
  std::vector<int> points, lines;
};

// One view with depths per keypoint (non-finite: none), as an RGB-D SLAM
// starts (ORB-SLAM2's RGB-D initialisation): the view is the world frame and
// every keypoint with a depth becomes a point (not only the nearest, as on
// later keyframes: they would crowd on one near object, and the map has
// nothing else yet). keyframe2 stays -1, lines come with the next keyframe.
// None (and the map left untouched) when fewer than `min_points` keypoints
// have a depth.
std::optional<InitialMap> buildDepthMap(VisualMap& map, const InitializationView& view,
                                        const std::vector<double>& depths, const PinholeIntrinsics& intrinsics,
                                        int min_points);

// None (and the map left empty) when fewer than `min_points` points survive the BA.
std::optional<InitialMap> buildInitialMap(VisualMap& map, const InitializationView& view1,
                                          const InitializationView& view2, const TwoViewInitialization& init,
                                          const std::vector<TwoViewMatch>& matches,
                                          const PinholeIntrinsics& intrinsics, const VisualConfig& config,
                                          int min_points);

}  // namespace lvslam::visual
