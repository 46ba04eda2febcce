#include "lvslam/fusion/fusion_framework.h"

#include <algorithm>
#include <cmath>

#include "lvslam/fusion/sphere_index.h"
#include "lvslam/visual/geometry/surface_depth.h"

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
  std::vector<SphereFeature> features = featuresInCamera(T_world_lidar);
  result.lidar_features = features.size();
  if (features.empty()) return result;
  // A segment's arc samples lie between its end rays, inside the cap round
  // the optical axis that holds every end ray (a cap under 90 deg is convex
  // on the sphere); only a feature within the neighbour angle of that cap
  // can be a sample's neighbour, the others would only make the index larger.
  double widest = 0.0;
  for (const ImageSegment& segment : segments)
    for (const Eigen::Vector2d& end : {segment.start, segment.end})
      widest = std::max(widest, std::acos(std::clamp(camera_.unproject(end).normalized().z(), -1.0, 1.0)));
  const double cone_cosine = std::cos(std::min(M_PI, widest + config_.max_neighbour_angle_deg * M_PI / 180.0));
  std::erase_if(features, [cone_cosine](const SphereFeature& f) {
    return f.p_camera.z() < cone_cosine * f.p_camera.norm();
  });
  const SphereIndex index(features);  // possibly empty: every segment is then far on the sphere
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
  std::vector<visual::PixelDepth> samples;
  for (const SphereFeature& f : featuresInCamera(T_world_lidar)) {
    const auto px = camera_.project(f.p_camera);
    if (px && camera_.inImage(*px)) samples.push_back({*px, f.p_camera.z()});
  }
  return visual::surfaceDepths(samples, pixels, max_pixel_distance, camera_.width(), camera_.height());
}

}  // namespace lvslam::fusion
