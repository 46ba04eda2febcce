#include "lvslam/sim/bvh.h"

#include <algorithm>
#include <numeric>

namespace lvslam::sim {

namespace {
constexpr int kLeafSize = 2;
constexpr int kMaxDepth = 60;  // the traversal stack holds 64 entries
}  // namespace

Bvh::Bvh(const std::vector<AlignedBox>& boxes) {
  items_.resize(boxes.size());
  std::iota(items_.begin(), items_.end(), 0);
  if (!boxes.empty()) build(boxes, 0, static_cast<int>(boxes.size()), 0);
}

// Median split along the widest axis of the box centres.
int Bvh::build(const std::vector<AlignedBox>& boxes, int first, int count, int depth) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  AlignedBox box, centres;
  for (int i = first; i < first + count; ++i) {
    box.extend(boxes[items_[i]]);
    centres.extend(0.5 * (boxes[items_[i]].min + boxes[items_[i]].max));
  }
  nodes_[index].box = box;
  if (count <= kLeafSize || depth >= kMaxDepth) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return index;
  }
  int axis = 0;
  (centres.max - centres.min).maxCoeff(&axis);
  const int mid = first + count / 2;
  std::nth_element(items_.begin() + first, items_.begin() + mid, items_.begin() + first + count, [&](int a, int b) {
    const double ca = boxes[a].min[axis] + boxes[a].max[axis], cb = boxes[b].min[axis] + boxes[b].max[axis];
    return ca != cb ? ca < cb : a < b;
  });
  const int left = build(boxes, first, mid - first, depth + 1);
  const int right = build(boxes, mid, first + count - mid, depth + 1);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

}  // namespace lvslam::sim
