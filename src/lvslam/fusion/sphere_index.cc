#include "lvslam/fusion/sphere_index.h"

#include <nanoflann.hpp>

#include "lvslam/fusion/sphere_geometry.h"

namespace lvslam::fusion {

namespace {

// nanoflann's dataset adaptor over a vector of unit bearings.
struct BearingCloud {
  std::vector<Eigen::Vector3d> bearings;
  std::size_t kdtree_get_point_count() const { return bearings.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const { return bearings[i][static_cast<int>(dim)]; }
  template <class BBox>
  bool kdtree_get_bbox(BBox&) const { return false; }
};

using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, BearingCloud>,
                                                   BearingCloud, 3, std::size_t>;

}  // namespace

struct SphereIndex::Tree {
  BearingCloud cloud;
  std::unique_ptr<KdTree> kdtree;
};

SphereIndex::SphereIndex(const std::vector<SphereFeature>& features) : tree_(std::make_unique<Tree>()) {
  tree_->cloud.bearings.reserve(features.size());
  for (const auto& f : features) tree_->cloud.bearings.push_back(bearing(f.p_camera));
  tree_->kdtree = std::make_unique<KdTree>(3, tree_->cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  if (!tree_->cloud.bearings.empty()) tree_->kdtree->buildIndex();
}

SphereIndex::~SphereIndex() = default;

bool SphereIndex::empty() const { return tree_->cloud.bearings.empty(); }

bool SphereIndex::nearest(const Eigen::Vector3d& b, SphereNeighbour& out) const {
  if (empty()) return false;
  std::size_t index = 0;
  double squared = 0.0;
  nanoflann::KNNResultSet<double, std::size_t> result(1);
  result.init(&index, &squared);
  tree_->kdtree->findNeighbors(result, b.data(), nanoflann::SearchParams());
  out.index = index;
  out.angle = chordToAngle(std::sqrt(squared));
  return true;
}

}  // namespace lvslam::fusion
