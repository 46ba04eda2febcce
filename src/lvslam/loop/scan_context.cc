#include "lvslam/loop/scan_context.h"

#include <algorithm>
#include <cmath>

namespace lvslam::loop {

ScanContext scanContextOf(const std::vector<lidar::FeaturePoint>& points_lidar, const ScanContextConfig& config) {
  std::vector<Eigen::Vector3f> positions;
  positions.reserve(points_lidar.size());
  for (const lidar::FeaturePoint& point : points_lidar) positions.push_back(point.p);
  return makeScanContext(positions, config);
}

ScanContext makeScanContext(const std::vector<Eigen::Vector3f>& points_lidar, const ScanContextConfig& config) {
  ScanContext sc;
  sc.bins = Eigen::MatrixXf::Zero(config.rings, config.sectors);
  const double ring_width = config.max_radius / config.rings;
  for (const Eigen::Vector3f& p : points_lidar) {
    const double range = std::hypot(static_cast<double>(p.x()), static_cast<double>(p.y()));
    if (!(range < config.max_radius) || !std::isfinite(p.z())) continue;
    const double azimuth = std::atan2(static_cast<double>(p.y()), static_cast<double>(p.x()));  // [-pi, pi]
    const int ring = std::min(static_cast<int>(range / ring_width), config.rings - 1);
    const int sector =
        std::clamp(static_cast<int>((azimuth + M_PI) / (2.0 * M_PI) * config.sectors), 0, config.sectors - 1);
    const auto height = static_cast<float>(std::max(static_cast<double>(p.z()) + config.height_offset, 1e-3));
    float& bin = sc.bins(ring, sector);
    bin = std::max(bin, height);
  }
  sc.ring_key = sc.bins.rowwise().mean();
  return sc;
}

ScanContextMatch compareScanContexts(const ScanContext& query, const ScanContext& candidate) {
  ScanContextMatch best;
  const auto sectors = static_cast<int>(query.bins.cols());
  if (candidate.bins.cols() != sectors || candidate.bins.rows() != query.bins.rows()) return best;
  const Eigen::VectorXf query_norms = query.bins.colwise().norm();
  const Eigen::VectorXf candidate_norms = candidate.bins.colwise().norm();
  for (int shift = 0; shift < sectors; ++shift) {
    double sum = 0.0;
    int count = 0;
    for (int j = 0; j < sectors; ++j) {
      const int k = (j + shift) % sectors;
      if (query_norms(j) <= 0.0f || candidate_norms(k) <= 0.0f) continue;
      sum += 1.0 - query.bins.col(j).dot(candidate.bins.col(k)) / (query_norms(j) * candidate_norms(k));
      ++count;
    }
    if (count == 0) continue;
    const double distance = sum / count;
    if (distance < best.distance) {
      best.distance = distance;
      best.shift = shift;
    }
  }
  const int signed_shift = best.shift > sectors / 2 ? best.shift - sectors : best.shift;
  best.yaw = 2.0 * M_PI * signed_shift / sectors;
  return best;
}

double ringKeyDistance(const ScanContext& a, const ScanContext& b) {
  if (a.ring_key.size() != b.ring_key.size()) return INFINITY;
  return static_cast<double>((a.ring_key - b.ring_key).norm());
}

}  // namespace lvslam::loop
