#pragma once
// Integer voxel coordinates and their hash, for the voxel hash maps of
// downsampling and of the local map (kiss-icp's VoxelHashMap idea).
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

namespace lvslam::lidar {

using VoxelKey = Eigen::Vector3i;

template <typename Vec3>
VoxelKey voxelOf(const Vec3& p, double voxel_size) {
  return VoxelKey(static_cast<int>(std::floor(p.x() / voxel_size)), static_cast<int>(std::floor(p.y() / voxel_size)),
                  static_cast<int>(std::floor(p.z() / voxel_size)));
}

struct VoxelKeyHash {
  std::size_t operator()(const VoxelKey& k) const {
    // Teschner et al. 2003 spatial hash primes.
    const auto x = static_cast<std::uint32_t>(k.x()), y = static_cast<std::uint32_t>(k.y()),
               z = static_cast<std::uint32_t>(k.z());
    return static_cast<std::size_t>((x * 73856093u) ^ (y * 19349669u) ^ (z * 83492791u));
  }
};

}  // namespace lvslam::lidar
