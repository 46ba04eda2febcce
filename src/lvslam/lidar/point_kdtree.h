#pragma once
// nanoflann (1.4) KD-tree over a vector of points exposing `.p` (Eigen::Vector3f).
#include <cstddef>
#include <vector>

#include <nanoflann.hpp>

namespace lvslam::lidar {

template <typename Point>
struct PointCloudAdaptor {
  const std::vector<Point>& points;
  std::size_t kdtree_get_point_count() const { return points.size(); }
  float kdtree_get_pt(std::size_t i, std::size_t dim) const { return points[i].p[static_cast<int>(dim)]; }
  template <typename BBox>
  bool kdtree_get_bbox(BBox&) const {
    return false;
  }
};

template <typename Point>
using PointKdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, PointCloudAdaptor<Point>>,
                                                        PointCloudAdaptor<Point>, 3, std::size_t>;

// The (at most) k nearest points strictly closer than radius: the search
// prunes with the radius from the start, so a lone far point costs little
// (plain kNN would roam the tree for k neighbours only to drop them).
template <typename Point>
std::size_t knnWithinRadius(const PointKdTree<Point>& tree, const float* query, std::size_t k, float radius,
                            std::size_t* ids, float* dist_sq) {
  if (k == 0) return 0;
  nanoflann::KNNResultSet<float, std::size_t, std::size_t> result(k);
  result.init(ids, dist_sq);
  dist_sq[k - 1] = radius * radius;  // the initial worst distance; kept until k points are found
  tree.findNeighbors(result, query, nanoflann::SearchParams());
  return result.size();
}

}  // namespace lvslam::lidar
