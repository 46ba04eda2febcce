#include "lvslam/visual/module/odometry_map_correction.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>
#include <unordered_set>
#include <utility>

#include "lvslam/core/se3.h"

namespace lvslam::visual {

namespace {

// The graph's nodes: the window's keyframes first (free), then the held
// ones; and its edges once per pair of node indices.
struct CorrectionGraph {
  std::vector<int> ids;
  std::unordered_map<int, int> index;
  std::vector<PoseGraphNode> nodes;
  int free = 0;
  std::set<std::pair<int, int>> pairs;

  void add(const VisualMap& map, int id, bool held) {
    index[id] = static_cast<int>(ids.size());
    ids.push_back(id);
    PoseGraphNode node{map.keyframe(id).T_camera_world, map.odometryPrior(id)};
    node.fixed = held;
    nodes.push_back(node);
    free += !held;
  }
};

// Edges: covisible keyframes and, so the graph is connected, consecutive
// ones (the held predecessor to the window's first).
CorrectionGraph buildGraph(const VisualMap& map, const MapCorrectionConfig& config) {
  CorrectionGraph g;
  const auto& keyframes = map.keyframes();
  const auto size = static_cast<std::ptrdiff_t>(keyframes.size());
  const std::ptrdiff_t window = config.window_keyframes > 0 ? std::min<std::ptrdiff_t>(size, config.window_keyframes)
                                                            : size;
  const auto first_free = std::prev(keyframes.end(), window);  // ids grow with insertion: the newest
  for (auto it = first_free; it != keyframes.end(); ++it) g.add(map, it->first, false);
  // Held: the keyframe before the window (the chain goes on) and older ones sharing landmarks with it.
  if (first_free != keyframes.begin()) {
    g.pairs.insert({0, g.free});  // the predecessor's node index
    g.add(map, std::prev(first_free)->first, true);
  }
  for (int i = 0; i < g.free; ++i) {
    if (i > 0) g.pairs.insert({i - 1, i});
    for (const int other : map.covisibility().neighbours(g.ids[i], config.min_covisibility)) {
      if (!map.hasKeyframe(other)) continue;
      if (!g.index.count(other)) g.add(map, other, true);
      const int j = g.index.at(other);
      g.pairs.insert({std::min(i, j), std::max(i, j)});
    }
  }
  return g;
}

std::vector<PoseGraphEdge> edgesOf(const CorrectionGraph& g) {
  std::vector<PoseGraphEdge> edges;
  edges.reserve(g.pairs.size());
  for (const auto& [a, b] : g.pairs)
    edges.push_back({a, b, g.nodes[a].T_camera_world * g.nodes[b].T_camera_world.inverse()});
  return edges;
}

// Landmarks move with their first observer, when it moved: those are all
// in the window keyframes' tables.
void moveLandmarks(VisualMap& map, const std::vector<int>& window, const MapCorrectionResult& result) {
  std::unordered_set<int> points, lines;
  for (const int kf : window) {
    const Keyframe& k = map.keyframe(kf);
    for (const int id : k.point_landmark) {
      if (id < 0 || !points.insert(id).second) continue;
      PointLandmark& p = map.point(id);
      if (p.observations.empty()) continue;
      const auto M = result.T_new_old.find(p.observations.front().keyframe);
      if (M != result.T_new_old.end()) p.p_world = M->second * p.p_world;
    }
    for (const int id : k.line_landmark) {
      if (id < 0 || !lines.insert(id).second) continue;
      LineLandmark& l = map.line(id);
      if (l.observations.empty()) continue;
      const auto found = result.T_new_old.find(l.observations.front().keyframe);
      if (found == result.T_new_old.end()) continue;
      const Eigen::Isometry3d& M = found->second;
      l.line_world = l.line_world.transformed(M);
      l.start_world = M * l.start_world;
      l.end_world = M * l.end_world;
      if (l.fusion_direction) l.fusion_direction = M.linear() * *l.fusion_direction;
    }
  }
}

}  // namespace

MapCorrectionResult correctMapWithOdometry(VisualMap& map, const MapCorrectionConfig& config) {
  MapCorrectionResult result;
  CorrectionGraph g = buildGraph(map, config);
  result.keyframes = g.free;
  result.held_keyframes = static_cast<int>(g.ids.size()) - g.free;
  if (g.ids.size() < 2) return result;
  const std::vector<PoseGraphEdge> edges = edgesOf(g);
  result.graph = optimizePoseGraph(g.nodes, edges, config.graph);
  if (!result.graph.solved) return result;

  // The map still holds the old poses until each keyframe is written back.
  const std::vector<int> window(g.ids.begin(), g.ids.begin() + g.free);
  for (int i = 0; i < g.free; ++i) {
    Eigen::Isometry3d& T_camera_world = map.keyframe(g.ids[i]).T_camera_world;
    const Eigen::Isometry3d& T_new = g.nodes[i].T_camera_world;
    const Eigen::Isometry3d M = T_new.inverse() * T_camera_world;
    const Eigen::Vector3d shift = T_camera_world.inverse().translation() - T_new.inverse().translation();
    result.max_shift_m = std::max(result.max_shift_m, shift.norm());
    result.max_rotation_deg = std::max(result.max_rotation_deg, rotationAngle(M) * 180.0 / M_PI);
    result.T_new_old[g.ids[i]] = M;
    T_camera_world = T_new;
  }
  moveLandmarks(map, window, result);
  return result;
}

}  // namespace lvslam::visual
