#include "lvslam/visual/data/covisibility_graph.h"

#include <algorithm>
#include <utility>

namespace lvslam::visual {

void CovisibilityGraph::addWeight(int a, int b, int delta) {
  if (a == b || delta == 0) return;
  for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
    auto& row = edges_[from];
    const int w = (row[to] += delta);
    if (w <= 0) row.erase(to);
    if (row.empty()) edges_.erase(from);
  }
}

void CovisibilityGraph::removeNode(int keyframe) {
  const auto it = edges_.find(keyframe);
  if (it == edges_.end()) return;
  for (const auto& [other, w] : it->second) {
    auto& row = edges_[other];
    row.erase(keyframe);
    if (row.empty()) edges_.erase(other);
  }
  edges_.erase(keyframe);
}

int CovisibilityGraph::weight(int a, int b) const {
  const auto it = edges_.find(a);
  if (it == edges_.end()) return 0;
  const auto jt = it->second.find(b);
  return jt == it->second.end() ? 0 : jt->second;
}

std::vector<int> CovisibilityGraph::neighbours(int keyframe, int min_weight) const {
  std::vector<std::pair<int, int>> list;  // (weight, id)
  const auto it = edges_.find(keyframe);
  if (it != edges_.end()) {
    for (const auto& [other, w] : it->second) {
      if (w >= min_weight) list.emplace_back(w, other);
    }
  }
  std::sort(list.begin(), list.end(), [](const auto& x, const auto& y) {
    return x.first != y.first ? x.first > y.first : x.second < y.second;
  });
  std::vector<int> ids;
  ids.reserve(list.size());
  for (const auto& [w, id] : list) ids.push_back(id);
  return ids;
}

std::vector<int> CovisibilityGraph::bestNeighbours(int keyframe, size_t n) const {
  std::vector<int> ids = neighbours(keyframe, 1);
  if (ids.size() > n) ids.resize(n);
  return ids;
}

}  // namespace lvslam::visual
