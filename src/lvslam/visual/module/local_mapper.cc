#include "lvslam/visual/module/local_mapper.h"

#include <set>

#include "lvslam/visual/geometry/segment_trimming.h"

namespace lvslam::visual {

namespace {

void addRecent(UsageTable& table, const std::vector<int>& ids, int keyframe) {
  for (const int id : ids) table[id] = {keyframe, 1, 1};
}

void count(UsageTable& table, const std::vector<int>& ids, int LandmarkUsage::*field) {
  for (const int id : ids) {
    const auto it = table.find(id);
    if (it != table.end()) ++(it->second.*field);
  }
}

}  // namespace

LocalMapper::LocalMapper(const LocalMapperConfig& config, const PinholeIntrinsics& intrinsics)
    : config_(config), K_(intrinsics) {}

void LocalMapper::addRecentPoints(const std::vector<int>& ids, int keyframe) { addRecent(recent_points_, ids, keyframe); }
void LocalMapper::addRecentLines(const std::vector<int>& ids, int keyframe) { addRecent(recent_lines_, ids, keyframe); }

void LocalMapper::countTracking(const std::vector<int>& visible_points, const std::vector<int>& found_points,
                                const std::vector<int>& visible_lines, const std::vector<int>& found_lines) {
  count(recent_points_, visible_points, &LandmarkUsage::visible);
  count(recent_points_, found_points, &LandmarkUsage::found);
  count(recent_lines_, visible_lines, &LandmarkUsage::visible);
  count(recent_lines_, found_lines, &LandmarkUsage::found);
}

void LocalMapper::reset() {
  recent_points_.clear();
  recent_lines_.clear();
}

void LocalMapper::createLandmarks(VisualMap& map, int keyframe, LocalMappingResult& result) {
  std::vector<int> neighbours = map.covisibility().bestNeighbours(keyframe, config_.point_neighbours);
  for (const int nb : neighbours) {
    const std::vector<int> points = triangulateNewPoints(map, keyframe, nb, K_, config_.points);
    addRecentPoints(points, keyframe);
    result.new_points += static_cast<int>(points.size());
  }
  for (size_t i = 0; i < neighbours.size() && i < config_.line_neighbours; ++i) {
    const std::vector<LineMatch> matches =
        matchLines(map.keyframe(keyframe).features, map.keyframe(neighbours[i]).features, config_.line_matching);
    const std::vector<int> lines = createLineLandmarks(map, keyframe, neighbours[i], matches, K_, config_.lines);
    addRecentLines(lines, keyframe);
    result.new_lines += static_cast<int>(lines.size());
  }
}

// Endpoint trimming after BA (Structure PLP, after Zhang et al. 2015).
void LocalMapper::trimLines(VisualMap& map, const std::vector<int>& window) const {
  Eigen::Matrix3d K;
  K << K_.fx, 0, K_.cx, 0, K_.fy, K_.cy, 0, 0, 1;
  std::set<int> lines;
  for (const int kf : window) {
    if (!map.hasKeyframe(kf)) continue;
    for (const int l : map.keyframe(kf).line_landmark)
      if (l >= 0) lines.insert(l);
  }
  for (const int id : lines) {  // all alive: keyframes observe no removed landmark
    LineLandmark& line = map.line(id);
    std::vector<SegmentObservation> observations;
    for (const Observation& o : line.observations) {
      const Keyframe& k = map.keyframe(o.keyframe);
      observations.push_back({k.T_camera_world, k.features.lines[o.index].start, k.features.lines[o.index].end});
    }
    const auto trimmed = trimSegment(line.line_world, K, observations);
    if (!trimmed) {
      map.removeLine(id);
      continue;
    }
    line.start_world = trimmed->start_world;
    line.end_world = trimmed->end_world;
  }
}

LocalMappingResult LocalMapper::process(VisualMap& map, int keyframe) {
  LocalMappingResult result;
  createLandmarks(map, keyframe, result);
  const PointMergingResult merging = mergeWithNeighbours(map, keyframe, K_, config_.merging);
  result.added_observations = merging.added;
  result.merged_points = merging.merged;
  const std::vector<LineDepth> depths_before = lineDepths(map, keyframe);
  result.ba_usable = adjustLocalWindow(map, keyframe, K_, config_.window).usable;
  const std::vector<int> window = map.localWindow(keyframe, config_.window.window_size);
  trimLines(map, window);
  result.depth_outlier_lines =
      static_cast<int>(removeLineDepthOutliers(map, keyframe, depths_before, config_.depth_check).size());
  result.culled_points = cullRecentPoints(map, recent_points_, keyframe, config_.culling);
  result.culled_lines = cullRecentLines(map, recent_lines_, keyframe, config_.culling);
  if (config_.cull_keyframes) result.removed_keyframes = cullRedundantKeyframes(map, window, keyframe, config_.culling);
  return result;
}

}  // namespace lvslam::visual
