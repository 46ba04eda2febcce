#include "lvslam/fusion/lidar_bridge.h"

namespace lvslam::fusion {

FeatureShape shapeOf(lidar::FeatureClass cls) {
  if (lidar::isPlanar(cls)) return FeatureShape::kPlanar;
  if (lidar::isLinear(cls)) return FeatureShape::kLinear;
  return FeatureShape::kOther;
}

std::vector<TimedFeature> toTimedFeatures(const lidar::FeatureFrame& frame) {
  std::vector<TimedFeature> out;
  out.reserve(frame.points.size());
  for (std::size_t i = 0; i < frame.points.size(); ++i) {
    const lidar::FeaturePoint& fp = frame.points[i];
    TimedFeature f;
    f.p_lidar = fp.p.cast<double>();
    f.direction_lidar = fp.direction.cast<double>();
    f.shape = shapeOf(fp.cls);
    f.t = frame.timestamp;
    f.id = frame.id(i);
    out.push_back(f);
  }
  return out;
}

ConstantVelocityMotion motionOf(const lidar::FeatureFrame& frame) {
  // Any second time works: only the pose at frame.timestamp is ever asked for.
  return {frame.timestamp, frame.T_world_lidar, frame.timestamp + 1.0, frame.T_world_lidar};
}

std::size_t applyDirectionUpdates(lidar::LidarOdometry& odometry, std::span<const LinearDirectionUpdate> updates) {
  std::size_t changed = 0;
  for (const LinearDirectionUpdate& u : updates) {
    if (u.ids.empty() || !u.direction_world.allFinite() || u.direction_world.norm() < 1e-9) continue;
    changed += odometry.setLinearDirections(u.ids, u.direction_world);
  }
  return changed;
}

std::vector<ImageSegment> toImageSegments(const std::vector<visual::RawSegment>& segments) {
  std::vector<ImageSegment> out;
  out.reserve(segments.size());
  for (const visual::RawSegment& s : segments)
    out.push_back({Eigen::Vector2d(s.start.x, s.start.y), Eigen::Vector2d(s.end.x, s.end.y)});
  return out;
}

}  // namespace lvslam::fusion
