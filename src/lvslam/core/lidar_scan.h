#pragma once
// One LiDAR sweep as the sensor delivered it: raw points in the LiDAR frame,
// each at its own capture time (not motion-compensated).
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace lvslam {

struct LidarPoint {
  Eigen::Vector3f p = Eigen::Vector3f::Zero();  // metres, LiDAR frame at the point's own time
  float intensity = 0.0f;
  float time = 0.0f;   // capture time minus the scan timestamp, seconds
  std::uint16_t ring = 0;
};

struct LidarScan {
  double timestamp = 0.0;  // seconds; a point's absolute time is timestamp + point.time
  bool has_intensity = false;
  bool has_time = false;   // false: per-point times are unknown (all zero)
  bool has_ring = false;
  std::vector<LidarPoint> points;

  std::size_t size() const { return points.size(); }
  bool empty() const { return points.empty(); }
  double pointTime(std::size_t i) const { return timestamp + static_cast<double>(points[i].time); }
};

}  // namespace lvslam
