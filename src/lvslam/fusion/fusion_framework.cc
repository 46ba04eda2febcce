#include "lvslam/fusion/fusion_framework.h"

#include <algorithm>
#include <cmath>

#include "lvslam/fusion/sphere_index.h"
#include "lvslam/visual/geometry/surface_depth.h"

namespace lvslam::fusion {

namespace {

// Cosine of the widest angle between the optical axis and a pixel's ray,
// widened by `margin`: the image border's rays bound every pixel's, corners
// included, with or without lens distortion.
double viewConeCosine(const PinholeCamera& camera, double margin) {
  double widest = 0.0;
  const auto visit = [&](double u, double v) {
    const Eigen::Vector3d ray = camera.unproject({u, v}).normalized();
    widest = std::max(widest, std::acos(std::clamp(ray.z(), -1.0, 1.0)));
  };
  // The image spans [-0.5, size - 0.5] (pixel centres at integers).
  const double left = -0.5, right = camera.width() - 0.5, top = -0.5, bottom = camera.height() - 0.5, step = 4.0;
  for (double u = left; u < right; u += step) visit(u, top), visit(u, bottom);
  for (double v = top; v < bottom; v += step) visit(left, v), visit(right, v);
  visit(right, bottom);
  return std::cos(std::min(M_PI, widest + margin));
}

}  // namespace

FusionFramework::FusionFramework(const PinholeCamera& camera, const Eigen::Isometry3d& T_camera_lidar,
                                 const FusionConfig& config)
    : camera_(camera),
      T_camera_lidar_(T_camera_lidar),
      config_(config),
      accumulator_(config.accumulated_scans),
      reconstructor_(camera, config),
      view_cone_cosine_(viewConeCosine(camera, config.max_neighbour_angle_deg * M_PI / 180.0)) {}

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
  // Only a feature within the neighbour angle of some pixel's ray can be a
  // line's neighbour; the others would only make the index larger.
  std::erase_if(features, [this](const SphereFeature& f) {
    return f.p_camera.z() < view_cone_cosine_ * f.p_camera.norm();
  });
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
  std::vector<visual::PixelDepth> samples;
  for (const SphereFeature& f : featuresInCamera(T_world_lidar)) {
    const auto px = camera_.project(f.p_camera);
    if (px && camera_.inImage(*px)) samples.push_back({*px, f.p_camera.z()});
  }
  return visual::surfaceDepths(samples, pixels, max_pixel_distance, camera_.width(), camera_.height());
}

}  // namespace lvslam::fusion
