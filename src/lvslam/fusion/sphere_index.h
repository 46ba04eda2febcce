#pragma once
// A 3D KD-tree (nanoflann) over the bearings of LiDAR feature points on the
// unit sphere: nearest geometric neighbour of each arc sample.
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "lvslam/fusion/sphere_feature.h"

namespace lvslam::fusion {

struct SphereNeighbour {
  std::size_t index = 0;  // into the features given to the index
  double angle = 0.0;     // radians on the sphere
};

class SphereIndex {
 public:
  explicit SphereIndex(const std::vector<SphereFeature>& features);
  ~SphereIndex();
  SphereIndex(const SphereIndex&) = delete;
  SphereIndex& operator=(const SphereIndex&) = delete;

  bool empty() const;
  // Nearest feature to a unit bearing; none when the index is empty.
  bool nearest(const Eigen::Vector3d& bearing, SphereNeighbour& out) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace lvslam::fusion
