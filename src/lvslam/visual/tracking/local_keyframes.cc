#include "lvslam/visual/tracking/local_keyframes.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

namespace lvslam::visual {

LocalKeyframes selectLocalKeyframes(const VisualMap& map, const std::vector<int>& tracked_points,
                                    int reference_keyframe, const LocalKeyframeConfig& config) {
  std::map<int, int> votes;  // keyframe -> landmarks shared with the last frame
  for (const int id : tracked_points) {
    const auto it = map.points().find(id);
    if (it == map.points().end()) continue;
    for (const Observation& o : it->second.observations) ++votes[o.keyframe];
  }
  std::vector<std::pair<int, int>> ranked(votes.begin(), votes.end());  // (keyframe, votes)
  std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  LocalKeyframes out;
  std::set<int> chosen;
  const auto add = [&](int kf) {
    if (map.hasKeyframe(kf) && chosen.insert(kf).second) out.keyframes.push_back(kf);
  };
  add(reference_keyframe);
  if (!ranked.empty()) out.most_shared = ranked.front().first;
  for (size_t i = 0; i < ranked.size() && i < config.max_voted; ++i) add(ranked[i].first);
  for (size_t i = 0; i < ranked.size() && i < config.expanded; ++i) {
    for (const int nb : map.covisibility().bestNeighbours(ranked[i].first, config.neighbours_each)) add(nb);
  }
  return out;
}

std::vector<int> nearbyKeyframes(const VisualMap& map, const Eigen::Isometry3d& T_camera_world, double radius,
                                 const std::vector<int>& exclude, const LocalKeyframeConfig& config) {
  if (!(radius > 0.0) || config.nearby_max == 0) return {};
  const Eigen::Vector3d centre = T_camera_world.inverse().translation();
  const Eigen::Vector3d axis = T_camera_world.linear().row(2).transpose();  // optical axis in the world
  const double min_cos = std::cos(config.nearby_max_angle_deg * M_PI / 180.0);
  const std::set<int> skip(exclude.begin(), exclude.end());
  std::vector<std::pair<double, int>> near;  // (distance, keyframe)
  const std::size_t count = map.keyframes().size();
  std::size_t index = 0;  // ids grow with insertion, so the map's order is age
  for (const auto& [id, k] : map.keyframes()) {
    if (index++ + config.nearby_min_age >= count) break;
    if (skip.count(id)) continue;
    const double d = (k.T_camera_world.inverse().translation() - centre).norm();
    if (d < radius && k.T_camera_world.linear().row(2).dot(axis) >= min_cos) near.emplace_back(d, id);
  }
  const std::size_t n = std::min(near.size(), config.nearby_max);
  std::partial_sort(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(n), near.end());
  std::vector<int> out;
  for (std::size_t i = 0; i < n; ++i) out.push_back(near[i].second);
  return out;
}

}  // namespace lvslam::visual
