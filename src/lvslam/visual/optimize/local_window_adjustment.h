#pragma once
// Local bundle adjustment of the map around a keyframe (ORB-SLAM's local
// mapping BA): the keyframe and its most covisible neighbours are optimised
// with every landmark they see; other keyframes seeing those landmarks take
// part fixed. Observations found to be outliers are removed from the map.
#include "lvslam/visual/data/visual_map.h"
#include "lvslam/visual/optimize/bundle_adjustment.h"

namespace lvslam::visual {

struct LocalWindowConfig {
  size_t window_size = 10;  // the keyframe and its n - 1 best covisible neighbours
  // Gauge when no keyframe outside the window sees the landmarks (at the
  // start of the map): the oldest keyframes of the window are held fixed.
  int fixed_oldest = 2;
  BundleAdjustmentConfig ba;
};

struct LocalWindowResult {
  bool usable = false;
  int optimised_keyframes = 0, fixed_keyframes = 0;
  int removed_point_observations = 0, removed_line_observations = 0;
};

LocalWindowResult adjustLocalWindow(VisualMap& map, int keyframe, const PinholeIntrinsics& intrinsics,
                                    const LocalWindowConfig& config = {});

}  // namespace lvslam::visual
