#include "lvslam/lidar/local_map.h"

#include <cmath>

#include <tsl/robin_set.h>

namespace lvslam::lidar {

void LocalMap::update(const FeatureFrame& frame) {
  insert(frame);
  prune(frame.T_world_lidar.translation().cast<float>(), frame.seq);
  limitRefinedRate();
}

void LocalMap::insert(const FeatureFrame& frame) {
  const Eigen::Isometry3f T = frame.T_world_lidar.cast<float>();
  const Eigen::Matrix3f R = T.linear();
  const std::size_t cap = static_cast<std::size_t>(config_.max_points_per_voxel);
  for (std::size_t i = 0; i < frame.points.size(); ++i) {
    const FeaturePoint& fp = frame.points[i];
    MapPoint mp{T * fp.p, R * fp.direction, fp.cls, fp.refined, frame.id(i)};
    std::vector<MapPoint>& cell = voxels_[voxelOf(mp.p, config_.voxel_size)];
    if (cell.size() >= cap) continue;
    cell.push_back(mp);
    ++size_;
    refined_ += mp.refined ? 1 : 0;
  }
}

void LocalMap::prune(const Eigen::Vector3f& sensor_position, std::uint32_t newest_seq) {
  const float radius = static_cast<float>(config_.radius);
  const float radius_sq = radius * radius;
  const std::uint32_t age = static_cast<std::uint32_t>(config_.max_frame_age);
  const std::uint32_t oldest_seq = newest_seq > age ? newest_seq - age : 0;
  const float voxel = static_cast<float>(config_.voxel_size);
  const float half_diagonal = 0.5f * std::sqrt(3.0f) * voxel;
  for (auto it = voxels_.begin(); it != voxels_.end();) {
    std::vector<MapPoint>& cell = it.value();
    // Points enter a voxel in frame order, so its first point is its oldest;
    // a young voxel wholly inside the radius keeps everything.
    const Eigen::Vector3f centre = (it->first.cast<float>() + Eigen::Vector3f::Constant(0.5f)) * voxel;
    if (frameOf(cell.front().id) >= oldest_seq && (centre - sensor_position).norm() + half_diagonal < radius) {
      ++it;
      continue;
    }
    const auto removed = std::erase_if(cell, [&](const MapPoint& mp) {
      const bool drop = frameOf(mp.id) < oldest_seq || (mp.p - sensor_position).squaredNorm() > radius_sq;
      if (drop) refined_ -= mp.refined ? 1 : 0;
      return drop;
    });
    size_ -= removed;
    it = cell.empty() ? voxels_.erase(it) : std::next(it);
  }
}

// Paper, "Improved storage of fusion-enhanced point cloud": above a rate alpha
// of refined points, downsample the refined ones until the rate is below it.
void LocalMap::limitRefinedRate() {
  const double alpha = config_.refined_rate_alpha;
  if (alpha >= 1.0 || refinedRate() <= alpha) return;
  const std::size_t unrefined = size_ - refined_;
  const auto target = static_cast<std::size_t>(std::floor(alpha * static_cast<double>(unrefined) / (1.0 - alpha)));
  std::vector<const MapPoint*> refined;
  for (const auto& [key, cell] : voxels_)
    for (const MapPoint& mp : cell)
      if (mp.refined) refined.push_back(&mp);
  // Coarser and coarser voxels keep the survivors spread over the map.
  tsl::robin_set<FeatureId> keep;
  double voxel = 0.5 * config_.voxel_size;
  for (int attempt = 0; attempt < 12; ++attempt, voxel *= 1.5) {
    keep.clear();
    tsl::robin_set<VoxelKey, VoxelKeyHash> occupied;
    for (const MapPoint* mp : refined)
      if (occupied.insert(voxelOf(mp->p, voxel)).second) keep.insert(mp->id);
    if (keep.size() <= target) break;
  }
  if (keep.size() > target) {  // still too many at the coarsest grid: keep the first ones
    keep.clear();
    for (std::size_t i = 0; i < target; ++i) keep.insert(refined[i]->id);
  }
  for (auto it = voxels_.begin(); it != voxels_.end();) {
    std::erase_if(it.value(), [&](const MapPoint& mp) { return mp.refined && !keep.count(mp.id); });
    it = it.value().empty() ? voxels_.erase(it) : std::next(it);
  }
  recount();
}

void LocalMap::recount() {
  size_ = refined_ = 0;
  for (const auto& [key, cell] : voxels_) {
    size_ += cell.size();
    for (const MapPoint& mp : cell) refined_ += mp.refined ? 1 : 0;
  }
}

const MapPoint* LocalMap::nearest(const Eigen::Vector3f& p_world, FeatureClass cls, float max_distance) const {
  // The 2x2x2 block of voxels whose shared corner is nearest to the point.
  const double s = config_.voxel_size;
  const VoxelKey base = voxelOf(p_world, s);
  VoxelKey lower = base;
  for (int a = 0; a < 3; ++a)
    if (p_world[a] / s - base[a] < 0.5) --lower[a];
  const MapPoint* best = nullptr;
  float best_sq = max_distance * max_distance;
  for (int dx = 0; dx < 2; ++dx)
    for (int dy = 0; dy < 2; ++dy)
      for (int dz = 0; dz < 2; ++dz) {
        const auto it = voxels_.find(VoxelKey(lower.x() + dx, lower.y() + dy, lower.z() + dz));
        if (it == voxels_.end()) continue;
        for (const MapPoint& mp : it->second) {
          if (mp.cls != cls) continue;
          const float d_sq = (mp.p - p_world).squaredNorm();
          if (d_sq < best_sq) {
            best_sq = d_sq;
            best = &mp;
          }
        }
      }
  return best;
}

std::size_t LocalMap::setDirections(std::span<const FeatureId> ids, std::span<const Eigen::Vector3f> positions_world,
                                    const Eigen::Vector3f& direction_world) {
  std::size_t changed = 0;
  for (std::size_t i = 0; i < ids.size() && i < positions_world.size(); ++i) {
    const auto it = voxels_.find(voxelOf(positions_world[i], config_.voxel_size));
    if (it == voxels_.end()) continue;
    for (MapPoint& mp : voxels_.find(it->first).value()) {
      if (mp.id != ids[i]) continue;
      refined_ += mp.refined ? 0 : 1;
      mp.direction = direction_world;
      mp.refined = true;
      ++changed;
    }
  }
  limitRefinedRate();
  return changed;
}

std::vector<MapPoint> LocalMap::points() const {
  std::vector<MapPoint> all;
  all.reserve(size_);
  for (const auto& [key, cell] : voxels_) all.insert(all.end(), cell.begin(), cell.end());
  return all;
}

}  // namespace lvslam::lidar
