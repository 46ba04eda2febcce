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

}  // namespace lvslam::lidar
