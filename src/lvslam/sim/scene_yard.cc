#include <cmath>

#include "lvslam/sim/outdoor_parts.h"
#include "lvslam/sim/scene_setups.h"

namespace lvslam::sim {

namespace {

// A park bench: seat, back rest and two side frames.
void addBench(SceneBuilder& scene, const Eigen::Vector2d& xy, double yaw, int wood, int iron) {
  const Eigen::Matrix3d R = yawRotation(yaw);
  const Eigen::Vector2d ex = R.col(0).head<2>(), ey = R.col(1).head<2>();
  scene.uprightBox(xy, yaw, {1.8, 0.45, 0.05}, 0.42, wood);
  scene.uprightBox(xy - 0.22 * ey, yaw, {1.8, 0.05, 0.4}, 0.5, wood);
  for (const double s : {-0.8, 0.8}) scene.uprightBox(xy + s * ex, yaw, {0.06, 0.5, 0.42}, 0.0, iron);
}

}  // namespace

SceneSetup buildYardScene(SceneBuilder& scene) {
  // Paving stones with grout and weathering: corners everywhere on the ground
  // the camera looks at, nothing the LiDAR can use beyond the ground plane.
  const int paving = scene.texture(TextureKind::kTiles, 0.5, 0.22, 0.4, 0.12);
  scene.rect(Eigen::Vector3d(0, 0, 0), Eigen::Matrix3d::Identity(), 200.0, 200.0, paving);
  // Buildings 115-130 m away: seen by the camera, beyond the LiDAR's 100 m
  // from everywhere on the drive (within 12 m of the origin).
  addBuilding(scene, WallFrame{{-60, 120, 0}, {1, 0, 0}, {0, -1, 0}, 120.0, 14.0}, 14.0, 4);
  addBuilding(scene, WallFrame{{125, 50, 0}, {0, -1, 0}, {-1, 0, 0}, 100.0, 11.0}, 12.0, 3);
  addBuilding(scene, WallFrame{{40, -130, 0}, {-1, 0, 0}, {0, 1, 0}, 90.0, 9.0}, 12.0, 3);
  // Flat things on the paving, unique where the stones repeat: drain covers,
  // painted markings, patches of gravel and leaves (no height for the LiDAR).
  for (int i = 0; i < 90; ++i) {
    const double a = scene.rng().uniform(0.0, 2.0 * M_PI), r = scene.rng().uniform(0.3, 1.9);
    const Eigen::Vector2d xy(3.0 + 11.0 * r * std::cos(a), 0.5 + 7.0 * r * std::sin(a));
    const bool painted = scene.rng().uniform() < 0.4;
    const int look = painted ? scene.texture(TextureKind::kPoster, 0.85, 0.15, scene.rng().uniform(0.1, 0.25), 0.03)
                             : scene.texture(TextureKind::kNoise, scene.rng().uniform(0.15, 0.7), 0.1,
                                             scene.rng().uniform(0.1, 0.4), 0.1);
    // Each a little above the last: no two coplanar.
    scene.rect(Eigen::Vector3d(xy.x(), xy.y(), 0.002 + 0.0002 * i), yawRotation(scene.rng().uniform(0.0, M_PI)),
               scene.rng().uniform(0.3, 1.2), scene.rng().uniform(0.3, 1.2), look);
  }
  // A few small things near the drive.
  const int wood = scene.texture(TextureKind::kPlanks, 0.45, 0.2, 0.1, 0.04);
  const int iron = scene.texture(TextureKind::kPlain, 0.15, 0.05, 0.5, 0.02);
  const int stone = scene.texture(TextureKind::kNoise, 0.55, 0.3, 0.2, 0.06);
  addBench(scene, {0.0, 4.5}, 0.0, wood, iron);
  addBench(scene, {8.0, -1.5}, M_PI / 2, wood, iron);
  scene.uprightBox({-1.0, -2.0}, 0.3, {1.2, 1.2, 0.5}, 0.0, stone);  // planter
  for (const Eigen::Vector2d& xy : {Eigen::Vector2d(6.0, 5.0), Eigen::Vector2d(8.0, 5.0), Eigen::Vector2d(10.0, 5.0)})
    scene.cylinder(xy, 0.0, 0.8, 0.08, iron);  // bollards
  addLampPost(scene, {-14.0, 0.0}, 4.5);
  addLampPost(scene, {5.0, -11.0}, 4.5);

  SceneSetup setup = outdoorSetup({-6.0, -8.0}, {12.0, -8.0});
  // An uneven loop about 22 x 14 m around the benches and the planter.
  addEllipseLoop(scene, setup.path, {3.0, 0.5}, 11.0, 7.0, 14, 0.08);
  return setup;
}

}  // namespace lvslam::sim
