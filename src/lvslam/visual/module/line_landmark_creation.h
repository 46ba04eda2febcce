#pragma once
// New line landmarks from matched segments of two keyframes (the local
// mapper's line triangulation, Cao et al. Sec. III-D): two-view triangulation
// through the dual Plücker matrix, a reprojection check in both views, the
// extent from endpoint trimming, and the observations entered in the map.
#include <vector>

#include "lvslam/visual/data/visual_map.h"
#include "lvslam/visual/geometry/line_triangulation.h"
#include "lvslam/visual/match/line_matcher.h"
#include "lvslam/visual/residuals/pose_block.h"

namespace lvslam::visual {

struct LineCreationConfig {
  LineTriangulationConfig triangulation;
  double max_reprojection_px = 3.0;  // endpoint distance to the reprojected line, both views
};

// matches: index1 into keyframe1's lines, index2 into keyframe2's. Segments
// that already observe a landmark are skipped. Returns the new landmark ids.
std::vector<int> createLineLandmarks(VisualMap& map, int keyframe1, int keyframe2,
                                     const std::vector<LineMatch>& matches, const PinholeIntrinsics& intrinsics,
                                     const LineCreationConfig& config = {});

}  // namespace lvslam::visual
