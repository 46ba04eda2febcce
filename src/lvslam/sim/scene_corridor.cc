#include <cmath>

#include "lvslam/sim/indoor_parts.h"
#include "lvslam/sim/scene_setups.h"

namespace lvslam::sim {

namespace {

// A corridor door as they are built: the leaf and its architrave stand only a
// centimetre or so proud of the wall (in reach of the LiDAR's range noise),
// while their shades contrast with the wall for the camera.
void addFlushDoor(SceneBuilder& scene, const WallFrame& wall, double s, int leaf, int frame, int metal) {
  const double width = 0.9, height = 2.1, bar = 0.07;
  scene.wallBox(wall, s, 0.0, {width, height, 0.008}, leaf);
  scene.wallBox(wall, s - bar, 0.0, {bar, height + bar, 0.012}, frame);
  scene.wallBox(wall, s + width, 0.0, {bar, height + bar, 0.012}, frame);
  scene.wallBox(wall, s - bar, height, {width + 2 * bar, bar, 0.012}, frame);
  scene.wallBox(wall, s + width - 0.15, 1.0, {0.11, 0.02, 0.05}, metal);  // handle
}

}  // namespace

SceneSetup buildCorridorScene(SceneBuilder& scene) {
  // 240 m long so that its end walls stay beyond the LiDAR's 100 m from
  // everywhere the robot drives (x in [106, 136]): along the axis the LiDAR
  // sees only plain walls, flush doors and a flush ceiling.
  const double length = 240.0, width = 2.4, height = 2.8;
  // Speckled linoleum, not tiles: a grid repeating along the drive aliases
  // the camera's matches (first run: vision moved a fifth of the way).
  const ShellStyle style{scene.texture(TextureKind::kNoise, 0.45, 0.2, 0.25, 0.12),
                         scene.texture(TextureKind::kPlain, 0.85, 0.6, 1.0, 0.02),
                         scene.texture(TextureKind::kPlain, 0.75, 0.6, 1.0, 0.03),
                         scene.texture(TextureKind::kPlain, 0.25, 0.1, 1.0, 0.02)};
  const auto walls = addRoomShell(scene, length, width, height, style);
  const WallFrame &south = walls[0], &north = walls[2];
  const int leaf = scene.texture(TextureKind::kPlanks, 0.45, 0.2, 0.3, 0.03);
  const int frame = scene.texture(TextureKind::kPlain, 0.2, 0.1, 0.5, 0.02);
  const int metal = scene.texture(TextureKind::kPlain, 0.8, 0.2, 0.5, 0.0);
  // Repetitive doors every 6 m on both sides (the north wall runs from x =
  // length back to 0), posters between every other pair.
  for (double x = 3.0; x + 3.0 < length; x += 6.0) {
    addFlushDoor(scene, south, x, leaf, frame, metal);
    addFlushDoor(scene, north, length - x - 3.9, leaf, frame, metal);
    // Each door's own name plate, flat on the wall.
    addPoster(scene, south, x + 1.05, 1.45, 0.25, 0.18, false);
    addPoster(scene, north, length - x - 2.75, 1.45, 0.25, 0.18, false);
    if (static_cast<int>(x / 6.0) % 2 == 0) {
      addPoster(scene, south, x + 2.0, 1.0, 1.0, 0.7, false);
      addPoster(scene, north, length - x - 2.4, 1.1, 0.7, 0.9, false);
    }
  }
  // Posters where the robot turns and faces a wall from close by.
  addPoster(scene, north, length - 136.6, 0.5, 2.2, 1.5, false);  // the U-turn at x 135.7
  addPoster(scene, south, 102.9, 0.5, 2.0, 1.5, false);            // the U-turn at x 104.3
  const int panel = scene.texture(TextureKind::kPlain, 1.0, 1.0, 1.0, 0.0);
  for (double x = 1.5; x < length; x += 3.0)  // flush light panels
    scene.rect(Eigen::Vector3d(x, 0.5 * width, height - 0.004), Eigen::Matrix3d::Identity(), 0.3, 0.3, panel);

  SceneSetup setup = indoorSetup(0.012, {110.0, 1.2}, {130.0, 1.2});
  // Along the corridor on the right, a U-turn, back on the other side.
  for (double x = 106.0; x <= 134.0; x += 4.0) setup.path.waypoints.emplace_back(x, 0.8);
  setup.path.waypoints.emplace_back(135.7, 1.2);
  for (double x = 134.0; x >= 106.0; x -= 4.0) setup.path.waypoints.emplace_back(x, 1.6);
  setup.path.waypoints.emplace_back(104.3, 1.2);
  setDrive(setup.path, 1.0, 0.6, 0.5);
  setup.path.shake_deg = 0.4;
  return setup;
}

}  // namespace lvslam::sim
