#include "lvslam/sim/outdoor_parts.h"

#include <cmath>

#include "lvslam/sim/indoor_parts.h"

namespace lvslam::sim {

void addBuilding(SceneBuilder& scene, const WallFrame& wall, double depth, int floors) {
  const int brick = scene.texture(TextureKind::kBricks, scene.rng().uniform(0.35, 0.6), 0.75, 0.25, 0.04);
  const Eigen::Vector3d centre = wall.at(0.5 * wall.length, 0.5 * wall.height, -0.5 * depth);
  scene.box(centre, wall.axes(), Eigen::Vector3d(0.5 * wall.length, 0.5 * wall.height, 0.5 * depth), brick);
  const double storey = wall.height / floors, pitch = 3.2;
  const int columns = static_cast<int>((wall.length - 2.0) / pitch);
  const double margin = 0.5 * (wall.length - columns * pitch);
  const int entrance = columns / 2;
  for (int f = 0; f < floors; ++f) {
    for (int c = 0; c < columns; ++c) {
      const double s = margin + c * pitch + 0.6;
      if (f == 0 && c == entrance) {
        addDoor(scene, wall, s - 0.2, 2.2, 2.6);
        continue;
      }
      addWindow(scene, wall, s, f * storey + 0.9, 1.6, std::min(1.6, storey - 1.3));
    }
    // A cornice between floors: a long horizontal line in both sensors.
    if (f > 0) scene.wallBox(wall, 0.0, f * storey - 0.1, {wall.length, 0.12, 0.08}, brick);
  }
}

void addGate(SceneBuilder& scene, const Eigen::Vector2d& xy, double yaw, double opening, double fence_left,
             double fence_right) {
  const Eigen::Vector2d ex = yawRotation(yaw).col(0).head<2>();
  const int stone = scene.texture(TextureKind::kBricks, 0.55, 0.8, 0.3, 0.03);
  const int iron = scene.texture(TextureKind::kPlain, 0.12, 0.05, 0.5, 0.02);
  const int sign = scene.texture(TextureKind::kPoster, 0.9, 0.1, 0.15, 0.02);
  const double half = 0.5 * opening + 0.4;
  for (const double side : {-1.0, 1.0}) scene.uprightBox(xy + side * half * ex, yaw, {0.8, 0.8, 3.2}, 0.0, stone);
  scene.uprightBox(xy, yaw, {opening + 1.6, 0.6, 0.5}, 3.2, stone);
  scene.rect(Eigen::Vector3d(xy.x(), xy.y(), 3.45) - 0.31 * yawRotation(yaw).col(1),
             yawRotation(yaw) * Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix(),
             0.35 * opening, 0.2, sign);
  // Fence: a low wall, a top rail and vertical bars.
  for (const double side : {-1.0, 1.0}) {
    const double length = side < 0 ? fence_left : fence_right;
    const Eigen::Vector2d start = xy + side * (half + 0.4) * ex;
    const Eigen::Vector2d mid = start + side * 0.5 * length * ex;
    scene.uprightBox(mid, yaw, {length, 0.3, 0.6}, 0.0, stone);
    scene.uprightBox(mid, yaw, {length, 0.06, 0.06}, 1.9, iron);
    for (double d = 0.15; d < length; d += 0.3)
      scene.uprightBox(start + side * d * ex, yaw, {0.04, 0.04, 1.3}, 0.6, iron);
  }
}

void addTree(SceneBuilder& scene, const Eigen::Vector2d& xy) {
  const int bark = scene.texture(TextureKind::kBark, scene.rng().uniform(0.2, 0.35), 0.1, 0.5, 0.03);
  const int leaves = scene.texture(TextureKind::kNoise, scene.rng().uniform(0.2, 0.35), 0.05, 0.12, 0.05);
  const double trunk = scene.rng().uniform(2.2, 3.2), crown = scene.rng().uniform(1.4, 2.4);
  scene.cylinder(xy, 0.0, trunk + 0.5 * crown, scene.rng().uniform(0.12, 0.22), bark);
  scene.sphere(Eigen::Vector3d(xy.x(), xy.y(), trunk + crown), crown, leaves);
}

void addLampPost(SceneBuilder& scene, const Eigen::Vector2d& xy, double height) {
  const int metal = scene.texture(TextureKind::kPlain, 0.3, 0.1, 0.5, 0.02);
  const int lamp = scene.texture(TextureKind::kPlain, 0.95, 0.9, 0.5, 0.0);
  scene.cylinder(xy, 0.0, height, 0.07, metal);
  scene.uprightBox(xy, 0.0, {0.5, 0.25, 0.15}, height, lamp);
}

void addKerb(SceneBuilder& scene, const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  const int concrete = scene.texture(TextureKind::kNoise, 0.6, 0.4, 0.5, 0.05);
  const int paint = scene.texture(TextureKind::kPlain, 0.9, 0.9, 0.5, 0.03);
  const Eigen::Vector2d d = to - from;
  const double yaw = std::atan2(d.y(), d.x());
  scene.uprightBox(0.5 * (from + to), yaw, {d.norm(), 0.15, 0.12}, 0.0, concrete);
  const Eigen::Vector2d inward = yawRotation(yaw).col(1).head<2>();
  const Eigen::Vector2d stripe = 0.5 * (from + to) + 0.5 * inward;
  scene.rect(Eigen::Vector3d(stripe.x(), stripe.y(), 0.002), yawRotation(yaw), 0.5 * d.norm(), 0.06, paint);
}

}  // namespace lvslam::sim
