#include "lvslam/visual/tracking/frame_tracker.h"

#include <algorithm>
#include <set>

namespace lvslam::visual {

namespace {

struct Projection {
  std::vector<ProjectedPoint> points;
  std::vector<int> point_ids;
  std::vector<ProjectedLine> lines;
  std::vector<int> line_ids;
};

bool projectInto(const Eigen::Isometry3d& T, const Eigen::Vector3d& p_world, const PinholeIntrinsics& K,
                 Eigen::Vector2d& pixel) {
  const Eigen::Vector3d p = T * p_world;
  if (!(p.z() > 0.05)) return false;
  pixel = {K.fx * p.x() / p.z() + K.cx, K.fy * p.y() / p.z() + K.cy};
  return pixel.allFinite();
}

bool insideImage(const Eigen::Vector2d& px, const FeatureFrame& f) {
  return px.x() >= 0.0 && px.y() >= 0.0 && px.x() < f.width && px.y() < f.height;
}

Projection projectLocalMap(const VisualMap& map, const LocalMap& local, const Eigen::Isometry3d& T,
                           const PinholeIntrinsics& K, double radius, const FeatureFrame& frame) {
  Projection out;
  for (const int id : local.points) {
    if (!map.hasPoint(id)) continue;
    const PointLandmark& p = map.point(id);
    Eigen::Vector2d px;
    if (!projectInto(T, p.p_world, K, px) || !insideImage(px, frame)) continue;
    out.points.push_back({px, radius, p.descriptor});
    out.point_ids.push_back(id);
  }
  for (const int id : local.lines) {
    if (!map.hasLine(id)) continue;
    const LineLandmark& l = map.line(id);
    Eigen::Vector2d a, b;
    if (l.descriptor.empty() || !projectInto(T, l.start_world, K, a) || !projectInto(T, l.end_world, K, b) ||
        !insideImage(0.5 * (a + b), frame)) {
      continue;
    }
    out.lines.push_back({a, b, l.descriptor});
    out.line_ids.push_back(id);
  }
  return out;
}

double invSigma2(const FeatureFrame& f, int keypoint) {
  const int level = f.keypoints[keypoint].octave;
  const auto& inv = f.pyramid.inv_sigma2;
  return level >= 0 && static_cast<size_t>(level) < inv.size() ? inv[level] : 1.0;
}

struct PassResult {
  PoseOptimizationResult pose;
  int matches = 0;
};

// One projection + matching + pose optimisation pass. Returns the pose result
// and leaves the inlier associations in the frame.
PassResult matchAndOptimize(const VisualMap& map, const Projection& proj, const Eigen::Isometry3d& T0,
                                        const PinholeIntrinsics& K, const LineMatcherConfig& line_config,
                                        const FrameTrackerConfig& config, TrackedFrame& frame) {
  const FeatureFrame& f = frame.features;
  const std::vector<PointMatch> pm = matchByProjection(proj.points, f, frame.grid, config.point_matching);
  const std::vector<LineMatch> lm = matchLinesByProjection(proj.lines, f, line_config);
  std::vector<PosePointObservation> points;
  std::vector<PoseLineObservation> lines;
  for (const PointMatch& m : pm)
    points.push_back({map.point(proj.point_ids[m.index1]).p_world, f.points[m.index2], invSigma2(f, m.index2)});
  for (const LineMatch& m : lm) {
    const LineSegment& s = f.lines[m.index2];
    lines.push_back({map.line(proj.line_ids[m.index1]).line_world, s.start, s.end, 1.0});
  }
  PassResult pass{optimizePose(T0, points, lines, K, config.pose), static_cast<int>(points.size() + lines.size())};
  const PoseOptimizationResult& result = pass.pose;
  std::fill(frame.point_landmark.begin(), frame.point_landmark.end(), -1);
  std::fill(frame.line_landmark.begin(), frame.line_landmark.end(), -1);
  frame.point_inliers = frame.line_inliers = 0;
  if (!result.success) return pass;
  for (size_t i = 0; i < pm.size(); ++i) {
    if (!result.point_inlier[i]) continue;
    frame.point_landmark[pm[i].index2] = proj.point_ids[pm[i].index1];
    ++frame.point_inliers;
  }
  for (size_t i = 0; i < lm.size(); ++i) {
    if (!result.line_inlier[i]) continue;
    frame.line_landmark[lm[i].index2] = proj.line_ids[lm[i].index1];
    ++frame.line_inliers;
  }
  return pass;
}

}  // namespace

LocalMap collectLocalMap(const VisualMap& map, int keyframe, size_t n, const std::vector<int>& extra_lines) {
  return collectLocalMap(map, map.localWindow(keyframe, n), extra_lines);
}

LocalMap collectLocalMap(const VisualMap& map, const std::vector<int>& keyframes, const std::vector<int>& extra_lines) {
  std::set<int> points, lines(extra_lines.begin(), extra_lines.end());
  for (const int kf : keyframes) {
    const Keyframe& k = map.keyframe(kf);
    for (const int p : k.point_landmark)
      if (p >= 0) points.insert(p);
    for (const int l : k.line_landmark)
      if (l >= 0) lines.insert(l);
  }
  return {{points.begin(), points.end()}, {lines.begin(), lines.end()}};
}

FrameTrackingResult trackLocalMap(const VisualMap& map, const LocalMap& local, const Eigen::Isometry3d& T_predicted,
                                  const PinholeIntrinsics& K, double radius_scale, const FrameTrackerConfig& config,
                                  TrackedFrame& frame) {
  FrameTrackingResult out;
  frame.point_landmark.assign(frame.features.points.size(), -1);
  frame.line_landmark.assign(frame.features.lines.size(), -1);
  LineMatcherConfig wide_lines = config.line_matching;
  wide_lines.max_line_distance_px *= config.line_distance_scale * radius_scale;
  const Projection first =
      projectLocalMap(map, local, T_predicted, K, config.search_radius_px * radius_scale, frame.features);
  const PoseOptimizationResult coarse = matchAndOptimize(map, first, T_predicted, K, wide_lines, config, frame).pose;
  if (!coarse.success) return out;
  const Projection second =
      projectLocalMap(map, local, coarse.T_camera_world, K, config.refine_radius_px, frame.features);
  const PassResult pass = matchAndOptimize(map, second, coarse.T_camera_world, K, config.line_matching, config, frame);
  const PoseOptimizationResult& fine = pass.pose;
  if (!fine.success || frame.point_inliers + frame.line_inliers < config.min_inliers) return out;
  frame.T_camera_world = fine.T_camera_world;
  frame.information = fine.information;
  out.success = true;
  out.matches = pass.matches;
  out.visible_points = second.point_ids;
  out.visible_lines = second.line_ids;
  return out;
}

TrackedObservations trackedObservations(const TrackedFrame& frame) {
  TrackedObservations out;
  const FeatureFrame& f = frame.features;
  for (size_t i = 0; i < frame.point_landmark.size(); ++i)
    if (frame.point_landmark[i] >= 0)
      out.points.push_back({frame.point_landmark[i], f.points[i].cast<float>(),
                            static_cast<float>(invSigma2(f, static_cast<int>(i)))});
  for (size_t i = 0; i < frame.line_landmark.size(); ++i)
    if (frame.line_landmark[i] >= 0)
      out.lines.push_back({frame.line_landmark[i], f.lines[i].start.cast<float>(), f.lines[i].end.cast<float>()});
  return out;
}

std::optional<Eigen::Isometry3d> relocateInMap(const VisualMap& map, const TrackedObservations& observations,
                                               const Eigen::Isometry3d& T_initial, const PinholeIntrinsics& intrinsics,
                                               const FrameTrackerConfig& config) {
  std::vector<PosePointObservation> points;
  std::vector<PoseLineObservation> lines;
  for (const TrackedPointObservation& o : observations.points) {
    if (map.hasPoint(o.landmark))
      points.push_back({map.point(o.landmark).p_world, o.pixel.cast<double>(), o.inv_sigma2});
  }
  for (const TrackedLineObservation& o : observations.lines) {
    if (map.hasLine(o.landmark))
      lines.push_back({map.line(o.landmark).line_world, o.start.cast<double>(), o.end.cast<double>(), 1.0});
  }
  const PoseOptimizationResult r = optimizePose(T_initial, points, lines, intrinsics, config.pose);
  if (!r.success || r.num_inliers < config.min_inliers) return std::nullopt;
  return r.T_camera_world;
}

}  // namespace lvslam::visual
