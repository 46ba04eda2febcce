#include "lvslam/visual/tracking/local_keyframes.h"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

namespace lvslam::visual {

LocalKeyframes selectLocalKeyframes(const VisualMap& map, const std::vector<int>& tracked_points,
                                    int reference_keyframe, const LocalKeyframeConfig& config) {
  std::map<int, int> votes;  // keyframe -> landmarks shared with the last frame
  for (const int id : tracked_points) {
    const auto it = map.points().find(id);
    if (it == map.points().end() || it->second.bad) continue;
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

}  // namespace lvslam::visual
