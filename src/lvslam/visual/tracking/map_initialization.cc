#include "lvslam/visual/tracking/map_initialization.h"

#include <cmath>

#include "lvslam/visual/match/feature_grid.h"

namespace lvslam::visual {

std::vector<DepthHint> depthHintsForKeypoints(const FeatureFrame& frame, const std::vector<PixelDepth>& hints,
                                              double radius_px) {
  std::vector<DepthHint> out;
  std::vector<Eigen::Vector2d> pixels;
  std::vector<double> depths;
  for (const PixelDepth& h : hints) {
    if (!h.pixel.allFinite() || !std::isfinite(h.depth) || !(h.depth > 0.0)) continue;
    pixels.push_back(h.pixel);
    depths.push_back(h.depth);
  }
  if (pixels.empty()) return out;
  const FeatureGrid grid(pixels, frame.width, frame.height, 16);
  std::vector<int> near;
  for (size_t i = 0; i < frame.keypoints.size(); ++i) {
    const Eigen::Vector2d kp(frame.keypoints[i].pt.x, frame.keypoints[i].pt.y);
    grid.query(kp, radius_px, near);
    int best = -1;
    double best_d2 = radius_px * radius_px;
    for (const int j : near) {
      const double d2 = (pixels[j] - kp).squaredNorm();
      if (d2 <= best_d2) {
        best_d2 = d2;
        best = j;
      }
    }
    if (best >= 0) out.push_back({static_cast<int>(i), depths[best]});
  }
  return out;
}

namespace {

int countGoodPoints(const VisualMap& map, const std::vector<int>& ids) {
  int n = 0;
  for (const int id : ids) n += map.hasPoint(id) && map.point(id).observations.size() >= 2;
  return n;
}

}  // namespace

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
