#pragma once
// Covisibility graph (ORB-SLAM): keyframes are nodes, an edge's weight is the
// number of landmarks (points and lines) both keyframes observe.
#include <cstddef>
#include <unordered_map>
#include <vector>

namespace lvslam::visual {

class CovisibilityGraph {
 public:
  // Changes the weight of edge (a, b) by delta; edges reaching 0 disappear.
  void addWeight(int a, int b, int delta);
  void removeNode(int keyframe);

  int weight(int a, int b) const;
  // Neighbours with weight >= min_weight, heaviest first (ties: smaller id first).
  std::vector<int> neighbours(int keyframe, int min_weight = 1) const;
  // At most n heaviest neighbours.
  std::vector<int> bestNeighbours(int keyframe, std::size_t n) const;

 private:
  std::unordered_map<int, std::unordered_map<int, int>> edges_;
};

}  // namespace lvslam::visual
