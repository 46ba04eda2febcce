#pragma once
// Bounding-volume hierarchy over the primitives' boxes, so a ray tests a
// handful of primitives instead of all of them.
#include <algorithm>
#include <vector>

#include "lvslam/sim/primitive.h"

namespace lvslam::sim {

class Bvh {
 public:
  struct Node {
    AlignedBox box;
    int left = -1, right = -1;  // children (inner node)
    int first = 0, count = 0;   // range in items() (leaf: count > 0)
  };

  Bvh() = default;
  explicit Bvh(const std::vector<AlignedBox>& boxes);

  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<int>& items() const { return items_; }  // primitive ids, leaf by leaf

  // Calls test(id) for every primitive whose leaf box the ray enters before
  // t_max; test may shrink t_max (nearest-hit search).
  template <typename TestPrimitive>
  void traverse(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double& t_max,
                TestPrimitive&& test) const {
    if (nodes_.empty()) return;
    const Eigen::Vector3d inv_dir = dir.cwiseInverse();
    int stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[stack[--top]];
      if (!node.box.hitBy(origin, inv_dir, t_max)) continue;
      if (node.count > 0) {
        for (int i = node.first; i < node.first + node.count; ++i) test(items_[i]);
      } else {
        stack[top++] = node.left;
        stack[top++] = node.right;
      }
    }
  }

 private:
  int build(const std::vector<AlignedBox>& boxes, int first, int count, int depth);

  std::vector<Node> nodes_;
  std::vector<int> items_;
};

}  // namespace lvslam::sim
