#include "lvslam/visual/tracking/map_initialization.h"

#include <algorithm>
#include <cmath>

#include "lvslam/visual/module/point_triangulation.h"

namespace lvslam::visual {

namespace {

int countGoodPoints(const VisualMap& map, const std::vector<int>& ids) {
  int n = 0;
  for (const int id : ids) n += map.hasPoint(id) && map.point(id).observations.size() >= 2;
  return n;
}

}  // namespace

std::optional<InitialMap> buildDepthMap(VisualMap& map, const InitializationView& view,
                                        const std::vector<double>& depths, const PinholeIntrinsics& intrinsics,
                                        int min_points) {
  const auto with_depth =
      std::count_if(depths.begin(), depths.end(), [](double z) { return std::isfinite(z) && z > 0.0; });
  if (depths.size() != view.features->points.size() || with_depth < min_points) return std::nullopt;
  InitialMap out;
  Keyframe k;
  k.timestamp = view.timestamp;
  k.features = *view.features;
  out.keyframe1 = map.addKeyframe(std::move(k));
  map.setKeypointDepths(out.keyframe1, depths);  // bundle adjustment keeps them as depth terms
  PointTriangulationConfig every_depth;
  every_depth.create_depth_points = true;
  every_depth.max_depth_points = static_cast<int>(with_depth);
  out.points = createDepthPoints(map, out.keyframe1, intrinsics, every_depth);
  return out;
}

std::optional<InitialMap> buildInitialMap(VisualMap& map, const InitializationView& view1,
                                          const InitializationView& view2, const TwoViewInitialization& init,
                                          const std::vector<TwoViewMatch>& matches,
                                          const PinholeIntrinsics& intrinsics, const VisualConfig& config,
                                          int min_points) {
  InitialMap out;
  Keyframe k1, k2;
  k1.timestamp = view1.timestamp;
  k1.features = *view1.features;
  k2.timestamp = view2.timestamp;
  k2.features = *view2.features;
  k2.T_camera_world = init.T_c2_c1;  // view 1 is the world frame
  out.keyframe1 = map.addKeyframe(std::move(k1));
  out.keyframe2 = map.addKeyframe(std::move(k2));
  for (size_t m = 0; m < matches.size(); ++m) {
    if (!init.triangulated[m]) continue;
    const int id = map.addPointLandmark(init.points_c1[m], view2.features->descriptors.row(matches[m].index2));
    map.addPointObservation(id, out.keyframe1, matches[m].index1);
    map.addPointObservation(id, out.keyframe2, matches[m].index2);
    out.points.push_back(id);
  }
  const std::vector<LineMatch> line_matches = matchLines(*view1.features, *view2.features, config.line_matching);
  out.lines = createLineLandmarks(map, out.keyframe1, out.keyframe2, line_matches, intrinsics);
  // The first keyframe fixes the gauge; the initial scale (metric or median
  // depth 1) is kept by starting BA from it.
  LocalWindowConfig window = config.local_window;
  window.fixed_oldest = 1;
  const LocalWindowResult ba = adjustLocalWindow(map, out.keyframe2, intrinsics, window);
  if (!ba.usable || countGoodPoints(map, out.points) < min_points) {
    map = VisualMap();
    return std::nullopt;
  }
  return out;
}

}  // namespace lvslam::visual
