#include "lvslam/sim/scene_builder.h"

namespace lvslam::sim {

Eigen::Matrix3d WallFrame::axes() const {
  Eigen::Matrix3d R;
  R.col(0) = along;
  R.col(1) = Eigen::Vector3d::UnitZ();
  R.col(2) = inward;
  return R;
}

Eigen::Matrix3d yawRotation(double yaw) { return Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix(); }

int SceneBuilder::texture(const Texture& texture) {
  textures_.push_back(texture);
  return static_cast<int>(textures_.size()) - 1;
}

int SceneBuilder::texture(TextureKind kind, double albedo, double albedo2, double scale, double roughness) {
  const auto seed = static_cast<std::uint64_t>(rng_.uniform() * 0x1.0p53);
  return texture(Texture{kind, albedo, albedo2, scale, roughness, seed});
}

void SceneBuilder::rect(const Eigen::Vector3d& center, const Eigen::Matrix3d& axes, double half_x, double half_y,
                        int texture) {
  primitives_.push_back({PrimitiveKind::kRect, axes, center, Eigen::Vector3d(half_x, half_y, 0.0), texture});
}

void SceneBuilder::glassPane(const Eigen::Vector3d& center, const Eigen::Matrix3d& axes, double half_x,
                             double half_y, int texture) {
  rect(center, axes, half_x, half_y, texture);
  primitives_.back().glass = true;
}

void SceneBuilder::box(const Eigen::Vector3d& center, const Eigen::Matrix3d& axes, const Eigen::Vector3d& half,
                       int texture) {
  primitives_.push_back({PrimitiveKind::kBox, axes, center, half, texture});
}

void SceneBuilder::uprightBox(const Eigen::Vector2d& xy, double yaw, const Eigen::Vector3d& size, double z0,
                              int texture) {
  box(Eigen::Vector3d(xy.x(), xy.y(), z0 + 0.5 * size.z()), yawRotation(yaw), 0.5 * size, texture);
}

void SceneBuilder::wallBox(const WallFrame& wall, double s, double z, const Eigen::Vector3d& size, int texture) {
  box(wall.at(s + 0.5 * size.x(), z + 0.5 * size.y(), 0.5 * size.z()), wall.axes(), 0.5 * size, texture);
}

void SceneBuilder::repeatShifted(std::size_t first, const Eigen::Vector3d& shift) {
  const std::size_t end = primitives_.size();
  for (std::size_t i = first; i < end; ++i) {
    Primitive copy = primitives_[i];
    copy.center += shift;
    primitives_.push_back(copy);
  }
}

void SceneBuilder::cylinder(const Eigen::Vector2d& xy, double z0, double z1, double radius, int texture) {
  primitives_.push_back({PrimitiveKind::kCylinder, Eigen::Matrix3d::Identity(),
                         Eigen::Vector3d(xy.x(), xy.y(), 0.5 * (z0 + z1)),
                         Eigen::Vector3d(radius, radius, 0.5 * (z1 - z0)), texture});
}

void SceneBuilder::sphere(const Eigen::Vector3d& center, double radius, int texture) {
  primitives_.push_back({PrimitiveKind::kSphere, Eigen::Matrix3d::Identity(), center,
                         Eigen::Vector3d::Constant(radius), texture});
}

}  // namespace lvslam::sim
