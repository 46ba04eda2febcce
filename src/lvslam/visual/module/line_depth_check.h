#pragma once
// Structure PLP-SLAM's depth check of line landmarks after local BA and
// endpoint trimming (Cao et al., Sec. III-D): the depth of each line's
// midpoint in the keyframe changes by some ratio; lines whose ratio departs
// from the scene's median ratio by more than 0.1 (0.2 for lines from fusion,
// which are trusted more) are outliers and removed.
#include <vector>

#include "lvslam/visual/data/visual_map.h"

namespace lvslam::visual {

struct LineDepthCheckConfig {
  double ratio = 0.1;
  double fusion_ratio = 0.2;
};

struct LineDepth {
  int line = -1;
  double depth = 0.0;  // midpoint z in the keyframe
};

// Midpoint depths of the keyframe's line landmarks that lie in front of it.
std::vector<LineDepth> lineDepths(const VisualMap& map, int keyframe);

// Compares with `before` (taken before BA) and removes the outliers.
// Returns the removed line ids.
std::vector<int> removeLineDepthOutliers(VisualMap& map, int keyframe, const std::vector<LineDepth>& before,
                                         const LineDepthCheckConfig& config = {});

}  // namespace lvslam::visual
