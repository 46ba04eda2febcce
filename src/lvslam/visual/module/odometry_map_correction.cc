#include "lvslam/visual/module/odometry_map_correction.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <unordered_map>
#include <utility>

namespace lvslam::visual {
namespace {

// The world-to-world motion of everything keyframe k carries: p_new = M p_old.
Eigen::Isometry3d landmarkMotion(const Eigen::Isometry3d& T_old_camera_world, const Eigen::Isometry3d& T_new_camera_world) {
  return T_new_camera_world.inverse() * T_old_camera_world;
}

}  // namespace

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

  std::vector<Eigen::Isometry3d> before;
  for (const PoseGraphNode& node : nodes) before.push_back(node.T_camera_world);
  result.graph = optimizePoseGraph(nodes, edges, config.graph);
  if (!result.graph.solved) return result;

  std::unordered_map<int, Eigen::Isometry3d> motion;  // per keyframe id
  for (size_t i = 0; i < ids.size(); ++i) {
    const Eigen::Isometry3d M = landmarkMotion(before[i], nodes[i].T_camera_world);
    motion[ids[i]] = M;
    map.keyframe(ids[i]).T_camera_world = nodes[i].T_camera_world;
    const Eigen::Vector3d shift = (before[i].inverse().translation() - nodes[i].T_camera_world.inverse().translation());
    const double angle = Eigen::AngleAxisd(M.linear()).angle() * 180.0 / M_PI;
    result.max_shift_m = std::max(result.max_shift_m, shift.norm());
    result.max_rotation_deg = std::max(result.max_rotation_deg, angle);
  }
  for (const auto& [id, point] : map.points()) {
    if (point.bad || point.observations.empty()) continue;
    const Eigen::Isometry3d& M = motion.at(point.observations.front().keyframe);
    PointLandmark& p = map.point(id);
    p.p_world = M * p.p_world;
  }
  for (const auto& [id, line] : map.lines()) {
    if (line.bad || line.observations.empty()) continue;
    const Eigen::Isometry3d& M = motion.at(line.observations.front().keyframe);
    LineLandmark& l = map.line(id);
    l.line_world = l.line_world.transformed(M);
    l.start_world = M * l.start_world;
    l.end_world = M * l.end_world;
    if (l.fusion_direction) l.fusion_direction = M.linear() * *l.fusion_direction;
  }
  return result;
}

}  // namespace lvslam::visual
