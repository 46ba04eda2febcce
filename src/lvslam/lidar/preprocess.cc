#include "lvslam/lidar/preprocess.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <tsl/robin_set.h>

#include "lvslam/lidar/grazing_returns.h"

namespace lvslam::lidar {

namespace {

constexpr float kMaxPointTime = 1.0f;  // seconds
// Range bands of this width share one voxel size, so that a voxel never
// mixes two sizes.
constexpr double kRangeBandWidth = 5.0;  // metres
constexpr std::size_t kMaxBand = 100;     // 500 m and beyond share the last band
constexpr double kMaxValidRange = 1e5;    // metres; farther "returns" are corrupt records

// Voxel key plus the range band it belongs to.
struct BandVoxelKey {
  VoxelKey voxel;
  int band = 0;
  bool operator==(const BandVoxelKey& other) const { return band == other.band && voxel == other.voxel; }
};

struct BandVoxelKeyHash {
  std::size_t operator()(const BandVoxelKey& k) const {
    return VoxelKeyHash{}(k.voxel) ^ (static_cast<std::size_t>(k.band) * 2654435761u);
  }
};

}  // namespace

double voxelSizeAt(double range, const PreprocessConfig& config) {
  const double band = std::floor(std::clamp(range, 0.0, kMaxBand * kRangeBandWidth) / kRangeBandWidth);
  const double far_edge = (band + 1.0) * kRangeBandWidth;
  return std::max(config.voxel_size, far_edge * std::tan(config.voxel_angle_deg * M_PI / 180.0));
}

std::vector<TimedPoint> rangeAdaptiveDownsample(const std::vector<TimedPoint>& points,
                                                const PreprocessConfig& config) {
  if (!(config.voxel_angle_deg > 0.0))
    return voxelDownsample(points, config.voxel_size, [](const TimedPoint& tp) { return tp.p; });
  std::array<double, kMaxBand + 1> band_voxel{};
  for (std::size_t band = 0; band < band_voxel.size(); ++band)
    band_voxel[band] = voxelSizeAt((static_cast<double>(band) + 0.5) * kRangeBandWidth, config);
  tsl::robin_set<BandVoxelKey, BandVoxelKeyHash> occupied;
  occupied.reserve(points.size());
  std::vector<TimedPoint> kept;
  kept.reserve(points.size() / 2);
  for (const TimedPoint& point : points) {
    const double range = point.p.norm();
    if (!(range < kMaxValidRange)) continue;  // non-finite or absurd: no voxel index for it
    const auto band = static_cast<std::size_t>(std::min(range, kMaxBand * kRangeBandWidth) / kRangeBandWidth);
    const double voxel = band_voxel[band];
    // Where the base size applies, bands share voxels (as without the angle).
    const int key_band = voxel > config.voxel_size ? static_cast<int>(band) : -1;
    if (occupied.insert({voxelOf(point.p, voxel), key_band}).second) kept.push_back(point);
  }
  return kept;
}

std::vector<TimedPoint> cropAndDownsample(const LidarScan& scan, const PreprocessConfig& config,
                                          double ring_neighbour_radius) {
  const float min_sq = static_cast<float>(config.min_range * config.min_range);
  const float max_sq = static_cast<float>(config.max_range * config.max_range);
  std::vector<TimedPoint> cropped;
  cropped.reserve(scan.points.size());
  for (const LidarPoint& point : scan.points) {
    if (!point.p.allFinite()) continue;
    const float range_sq = point.p.squaredNorm();
    if (range_sq < min_sq || range_sq > max_sq) continue;
    const float time = scan.has_time ? point.time : 0.0f;
    // A sweep lasts a fraction of a second: other times are corrupt records.
    if (!(std::abs(time) <= kMaxPointTime)) continue;
    cropped.push_back({point.p, time, scan.has_ring ? static_cast<int>(point.ring) : -1});
  }
  if (ring_neighbour_radius > 0.0) {
    const std::vector<bool> grazing = grazingReturns(cropped, ring_neighbour_radius);
    std::size_t kept = 0;
    for (std::size_t i = 0; i < cropped.size(); ++i)
      if (!grazing[i]) cropped[kept++] = cropped[i];
    cropped.resize(kept);
  }
  return rangeAdaptiveDownsample(cropped, config);
}

}  // namespace lvslam::lidar
