#include "lvslam/fusion/fusion_framework.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "lvslam/fusion/sphere_index.h"

namespace lvslam::fusion {

FusionFramework::FusionFramework(const PinholeCamera& camera, const Eigen::Isometry3d& T_camera_lidar,
                                 const FusionConfig& config)
    : camera_(camera),
      T_camera_lidar_(T_camera_lidar),
      config_(config),
      accumulator_(config.accumulated_scans),
      reconstructor_(camera, config) {}

void FusionFramework::addLidarScan(const std::vector<TimedFeature>& features, const ConstantVelocityMotion& motion) {
  accumulator_.addScan(features, motion);
}

std::vector<SphereFeature> FusionFramework::featuresInCamera(const Eigen::Isometry3d& T_world_lidar) const {
  return accumulator_.inCameraFrame(T_world_lidar * T_camera_lidar_.inverse());
}

FusionResult FusionFramework::process(double t_camera, const Eigen::Isometry3d& T_world_lidar,
                                      const std::vector<ImageSegment>& segments) const {
  FusionResult result;
  result.t_camera = t_camera;
  const std::vector<SphereFeature> features = featuresInCamera(T_world_lidar);
  result.lidar_features = features.size();
  if (features.empty()) return result;
  const SphereIndex index(features);
  const Eigen::Matrix3d R_world_camera = (T_world_lidar * T_camera_lidar_.inverse()).linear();
  for (std::size_t i = 0; i < segments.size(); ++i) {
    RejectReason why = RejectReason::kNone;
    auto line = reconstructor_.reconstruct(segments[i], features, index, &why);
    if (!line) {
      ++result.rejected[static_cast<std::size_t>(why)];
      continue;
    }
    line->segment_index = i;
    if (!line->linear_feature_ids.empty())
      result.lidar_updates.push_back({line->linear_feature_ids, R_world_camera * line->direction});
    result.lines.push_back(std::move(*line));
  }
  return result;
}

std::vector<double> FusionFramework::pointDepths(const Eigen::Isometry3d& T_world_lidar,
                                                 const std::vector<Eigen::Vector2d>& pixels,
                                                 double max_pixel_distance) const {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> depths(pixels.size(), kNaN);
  if (!(max_pixel_distance > 0.0)) return depths;
  // Bucket the projected LiDAR points in cells of max_pixel_distance.
  const double cell = max_pixel_distance;
  auto key = [cell](double u, double v) {
    const auto iu = static_cast<std::uint32_t>(static_cast<std::int32_t>(std::floor(u / cell)));
    const auto iv = static_cast<std::uint32_t>(static_cast<std::int32_t>(std::floor(v / cell)));
    return (static_cast<std::uint64_t>(iu) << 32) | iv;
  };
  std::unordered_map<std::uint64_t, std::vector<Eigen::Vector3d>> grid;  // (u, v, z)
  for (const SphereFeature& f : featuresInCamera(T_world_lidar)) {
    const auto px = camera_.project(f.p_camera);
    if (px && camera_.inImage(*px)) grid[key(px->x(), px->y())].emplace_back(px->x(), px->y(), f.p_camera.z());
  }
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    std::vector<double> near;
    for (int du = -1; du <= 1; ++du)
      for (int dv = -1; dv <= 1; ++dv) {
        const auto it = grid.find(key(pixels[i].x() + du * cell, pixels[i].y() + dv * cell));
        if (it == grid.end()) continue;
        for (const auto& q : it->second)
          if ((q.head<2>() - pixels[i]).norm() <= max_pixel_distance) near.push_back(q.z());
      }
    if (near.size() < 2) continue;
    // The nearest surface wins (points behind it show through by parallax);
    // it needs a second point within 5 % to count as a surface, not a stray.
    std::sort(near.begin(), near.end());
    double sum = 0.0;
    int count = 0;
    for (const double z : near)
      if (z <= near.front() * 1.05) sum += z, ++count;
    if (count >= 2) depths[i] = sum / count;
  }
  return depths;
}

}  // namespace lvslam::fusion
