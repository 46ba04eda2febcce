#pragma once
// The registration target: features of recent frames merged in the world
// frame in a voxel hash (kiss-icp's VoxelHashMap), downsampled by a cap per
// voxel, bounded by a radius around the sensor and by frame age, and holding
// at most a rate alpha of fusion-refined points (the paper's storage rule).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Geometry>
#include <tsl/robin_map.h>

#include "lvslam/lidar/feature_point.h"
#include "lvslam/lidar/lidar_config.h"
#include "lvslam/lidar/voxel_key.h"

namespace lvslam::lidar {

struct MapPoint {
  Eigen::Vector3f p = Eigen::Vector3f::Zero();          // world
  Eigen::Vector3f direction = Eigen::Vector3f::UnitZ();  // world
  FeatureClass cls = FeatureClass::kVertex;
  bool refined = false;
  FeatureId id = 0;
};

class LocalMap {
 public:
  explicit LocalMap(const LocalMapConfig& config) : config_(config) {}

  // Adds the frame's points through frame.T_world_lidar, then drops what is
  // too old or too far and applies the refined-rate rule.
  void update(const FeatureFrame& frame);

  // Nearest map point of the class within max_distance of p_world (searched
  // in the 2x2x2 voxels around it), or nullptr.
  const MapPoint* nearest(const Eigen::Vector3f& p_world, FeatureClass cls, float max_distance) const;

  // Sets the direction (world frame) of the map points with these ids, found
  // at their world positions; marks them refined. Returns how many changed.
  std::size_t setDirections(std::span<const FeatureId> ids, std::span<const Eigen::Vector3f> positions_world,
                            const Eigen::Vector3f& direction_world);

  std::size_t size() const { return size_; }
  std::size_t refinedCount() const { return refined_; }
  double refinedRate() const { return size_ == 0 ? 0.0 : static_cast<double>(refined_) / size_; }
  bool empty() const { return size_ == 0; }
  std::vector<MapPoint> points() const;

 private:
  void insert(const FeatureFrame& frame);
  void prune(const Eigen::Vector3f& sensor_position, std::uint32_t newest_seq);
  void limitRefinedRate();
  void recount();

  LocalMapConfig config_;
  tsl::robin_map<VoxelKey, std::vector<MapPoint>, VoxelKeyHash> voxels_;
  std::size_t size_ = 0;
  std::size_t refined_ = 0;
};

}  // namespace lvslam::lidar
