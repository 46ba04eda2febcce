#include "lvslam/visual/module/odometry_map_correction.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "lvslam/core/se3.h"

namespace lvslam::visual {

MapCorrectionResult correctMapWithOdometry(VisualMap& map, const MapCorrectionConfig& config) {
  MapCorrectionResult result;
  std::vector<int> ids;
  std::unordered_map<int, int> index;
  std::vector<PoseGraphNode> nodes;
  for (const auto& [id, keyframe] : map.keyframes()) {
    index[id] = static_cast<int>(ids.size());
    ids.push_back(id);
    nodes.push_back({keyframe.T_camera_world, map.odometryPrior(id)});
  }
  result.keyframes = static_cast<int>(nodes.size());
  if (nodes.size() < 2) return result;

  // Edges once per pair: covisible keyframes and, so the graph is connected,
  // consecutive ones.
  std::set<std::pair<int, int>> pairs;
  for (size_t i = 0; i < ids.size(); ++i) {
    if (i > 0) pairs.insert({static_cast<int>(i) - 1, static_cast<int>(i)});
    for (const int other : map.covisibility().neighbours(ids[i], config.min_covisibility)) {
      const auto it = index.find(other);
      if (it == index.end()) continue;
      const int j = it->second;
      pairs.insert({std::min<int>(i, j), std::max<int>(i, j)});
    }
  }
  std::vector<PoseGraphEdge> edges;
  edges.reserve(pairs.size());
  for (const auto& [a, b] : pairs)
    edges.push_back({a, b, nodes[a].T_camera_world * nodes[b].T_camera_world.inverse()});

  result.graph = optimizePoseGraph(nodes, edges, config.graph);
  if (!result.graph.solved) return result;

  // The map still holds the old poses until each keyframe is written back.
  for (size_t i = 0; i < ids.size(); ++i) {
    Eigen::Isometry3d& T_camera_world = map.keyframe(ids[i]).T_camera_world;
    const Eigen::Isometry3d M = nodes[i].T_camera_world.inverse() * T_camera_world;
    const Eigen::Vector3d shift = T_camera_world.inverse().translation() - nodes[i].T_camera_world.inverse().translation();
    result.max_shift_m = std::max(result.max_shift_m, shift.norm());
    result.max_rotation_deg = std::max(result.max_rotation_deg, rotationAngle(M) * 180.0 / M_PI);
    result.T_new_old[ids[i]] = M;
    T_camera_world = nodes[i].T_camera_world;
  }
  for (const auto& [id, point] : map.points()) {
    if (point.bad || point.observations.empty()) continue;
    const Eigen::Isometry3d& M = result.T_new_old.at(point.observations.front().keyframe);
    PointLandmark& p = map.point(id);
    p.p_world = M * p.p_world;
  }
  for (const auto& [id, line] : map.lines()) {
    if (line.bad || line.observations.empty()) continue;
    const Eigen::Isometry3d& M = result.T_new_old.at(line.observations.front().keyframe);
    LineLandmark& l = map.line(id);
    l.line_world = l.line_world.transformed(M);
    l.start_world = M * l.start_world;
    l.end_world = M * l.end_world;
    if (l.fusion_direction) l.fusion_direction = M.linear() * *l.fusion_direction;
  }
  return result;
}

}  // namespace lvslam::visual
