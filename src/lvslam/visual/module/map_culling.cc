#include "lvslam/visual/module/map_culling.h"

namespace lvslam::visual {

namespace {

template <typename Landmarks, typename Remove>
int cullRecent(const Landmarks& landmarks, UsageTable& recent, int current_keyframe, const CullingConfig& config,
               Remove remove) {
  int culled = 0;
  for (auto it = recent.begin(); it != recent.end();) {
    const auto found = landmarks.find(it->first);
    if (found == landmarks.end()) {
      it = recent.erase(it);
      continue;
    }
    const LandmarkUsage& u = it->second;
    const int age = current_keyframe - u.first_keyframe;
    const bool rarely_found = u.found < config.min_found_ratio * u.visible;
    const int observers = static_cast<int>(found->second.observations.size());
    if (rarely_found || (age >= config.probation_keyframes && observers < config.min_observations)) {
      remove(it->first);
      ++culled;
      it = recent.erase(it);
    } else if (age >= config.release_keyframes) {
      it = recent.erase(it);
    } else {
      ++it;
    }
  }
  return culled;
}

// Share of the keyframe's landmarks that enough other keyframes observe.
template <typename Landmarks>
void countRedundant(const Landmarks& landmarks, const std::vector<int>& table, int observers, int& total,
                    int& redundant) {
  for (const int id : table) {
    if (id < 0) continue;
    const auto& l = landmarks.at(id);
    ++total;
    if (static_cast<int>(l.observations.size()) - 1 >= observers) ++redundant;
  }
}

}  // namespace

int cullRecentPoints(VisualMap& map, UsageTable& recent, int current_keyframe, const CullingConfig& config) {
  return cullRecent(map.points(), recent, current_keyframe, config, [&](int id) { map.removePoint(id); });
}

int cullRecentLines(VisualMap& map, UsageTable& recent, int current_keyframe, const CullingConfig& config) {
  // Lines are matched less often than points: two observing keyframes suffice.
  CullingConfig lines = config;
  lines.min_observations = std::min(config.min_observations, 2);
  return cullRecent(map.lines(), recent, current_keyframe, lines, [&](int id) { map.removeLine(id); });
}

std::vector<int> cullRedundantKeyframes(VisualMap& map, const std::vector<int>& candidates, int keep,
                                        const CullingConfig& config) {
  std::vector<int> removed;
  if (map.keyframes().empty()) return removed;
  const int first = map.keyframes().begin()->first;
  for (const int kf : candidates) {
    if (kf == keep || kf == first || !map.hasKeyframe(kf)) continue;
    const Keyframe& k = map.keyframe(kf);
    int total = 0, redundant = 0;
    countRedundant(map.points(), k.point_landmark, config.redundant_observers, total, redundant);
    countRedundant(map.lines(), k.line_landmark, config.redundant_observers, total, redundant);
    if (total > 0 && redundant > config.redundant_ratio * total) {
      map.removeKeyframe(kf);
      removed.push_back(kf);
    }
  }
  return removed;
}

}  // namespace lvslam::visual
