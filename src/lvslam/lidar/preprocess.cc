#include "lvslam/lidar/preprocess.h"

#include <cmath>

namespace lvslam::lidar {

namespace {
constexpr float kMaxPointTime = 1.0f;  // seconds
}  // namespace

std::vector<TimedPoint> cropAndDownsample(const LidarScan& scan, const PreprocessConfig& config) {
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
  return voxelDownsample(cropped, config.voxel_size, [](const TimedPoint& tp) { return tp.p; });
}

}  // namespace lvslam::lidar
