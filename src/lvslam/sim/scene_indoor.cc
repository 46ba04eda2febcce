#include <cmath>

#include "lvslam/sim/indoor_parts.h"
#include "lvslam/sim/scene_setups.h"

namespace lvslam::sim {

Lighting indoorDay() {
  Lighting light;
  light.ambient = 0.6;
  light.toward_light = Eigen::Vector3d(0.35, 0.2, 0.9).normalized();
  light.directional = 0.6;
  light.sky = 0.0;
  return light;
}

Lighting indoorNight() {
  Lighting light = indoorDay();
  light.ambient = 0.05;
  light.directional = 0.03;
  return light;
}

SceneSetup indoorSetup(double exposure, const Eigen::Vector2d& walk_from, const Eigen::Vector2d& walk_to) {
  SceneSetup setup;
  setup.day = indoorDay();
  setup.night = indoorNight();
  setup.exposure = exposure;
  setup.person.from = walk_from;
  setup.person.to = walk_to;
  return setup;
}

void addEllipseLoop(SceneBuilder& scene, PathConfig& path, const Eigen::Vector2d& centre, double rx, double ry,
                    int count, double jitter) {
  for (int i = 0; i < count; ++i) {
    const double a = 2.0 * M_PI * i / count;
    const double r = 1.0 + scene.rng().uniform(-jitter, jitter);
    path.waypoints.emplace_back(centre.x() + rx * r * std::cos(a), centre.y() + ry * r * std::sin(a));
  }
}

void setDrive(PathConfig& path, double max_speed, double max_turn_rate, double acceleration) {
  path.max_speed = max_speed;
  path.max_turn_rate = max_turn_rate;
  path.acceleration = acceleration;
}

SceneSetup buildRoomScene(SceneBuilder& scene) {
  const ShellStyle style{scene.texture(TextureKind::kTiles, 0.55, 0.2, 0.6, 0.04),
                         scene.texture(TextureKind::kTiles, 0.85, 0.55, 0.6, 0.02),
                         scene.texture(TextureKind::kPlain, 0.75, 0.6, 1.0, 0.05),
                         scene.texture(TextureKind::kPlain, 0.2, 0.1, 1.0, 0.02)};
  const auto walls = addRoomShell(scene, 10.0, 8.0, 3.0, style);
  const WallFrame &south = walls[0], &east = walls[1], &north = walls[2], &west = walls[3];
  addDoor(scene, south, 1.0, 0.9, 2.1);
  addPoster(scene, south, 2.5, 1.2, 0.7, 1.0, true);
  addShelf(scene, south, 3.7, 1.6, 1.9);
  addWindow(scene, south, 6.2, 0.9, 1.8, 1.4);
  addPoster(scene, south, 8.6, 1.3, 0.6, 0.8, false);
  addWindow(scene, east, 1.0, 0.9, 1.8, 1.4);
  addPoster(scene, east, 3.5, 1.2, 1.0, 0.7, false);
  addShelf(scene, east, 5.0, 1.4, 2.0);
  addDoor(scene, east, 6.8, 0.9, 2.1);
  addShelf(scene, north, 0.4, 1.2, 1.8);
  addPoster(scene, north, 2.2, 1.1, 0.8, 1.1, true);
  addWindow(scene, north, 4.3, 0.9, 2.0, 1.4);
  addDoor(scene, north, 7.3, 0.9, 2.1);
  addPoster(scene, north, 8.8, 1.4, 0.6, 0.8, true);
  addPoster(scene, west, 0.8, 0.9, 1.6, 1.0, true);
  addWindow(scene, west, 3.4, 0.9, 1.6, 1.4);
  addShelf(scene, west, 5.6, 1.4, 1.9);
  addDesk(scene, {4.6, 7.25}, 0.0);
  addDesk(scene, {8.2, 0.75}, M_PI);
  addDesk(scene, {5.0, 4.0}, 0.1);
  addBoxStack(scene, {9.4, 4.2}, 0.2, 3);
  addBoxStack(scene, {0.6, 4.0}, -0.1, 2);
  addBoxStack(scene, {6.0, 7.5}, 0.4, 2);
  addCeilingLights(scene, {2.0, 2.0}, {8.0, 6.0}, 2.0, 3.0);

  SceneSetup setup = indoorSetup(0.012, {1.2, 2.2}, {1.2, 5.8});
  addEllipseLoop(scene, setup.path, {5.0, 4.0}, 2.9, 2.0, 10, 0.06);  // uneven, around the middle desk
  setDrive(setup.path, 0.4, 0.45, 0.25);
  return setup;
}

SceneSetup buildHallScene(SceneBuilder& scene) {
  const ShellStyle style{scene.texture(TextureKind::kTiles, 0.5, 0.15, 0.8, 0.05),
                         scene.texture(TextureKind::kPlain, 0.8, 0.6, 1.0, 0.03),
                         scene.texture(TextureKind::kBricks, 0.65, 0.3, 0.3, 0.05),
                         scene.texture(TextureKind::kPlain, 0.2, 0.1, 1.0, 0.02)};
  const double length = 30.0, width = 20.0, height = 6.0;
  const auto walls = addRoomShell(scene, length, width, height, style);
  for (const int w : {0, 2}) {  // long walls: windows, notice boards and doors
    for (double s = 1.5; s + 2.5 < length; s += 4.0) {
      addWindow(scene, walls[w], s, 2.8, 2.2, 2.4);
      addPoster(scene, walls[w], s + 0.3, 0.9, 1.2, 0.9, true);
    }
    addDoor(scene, walls[w], 14.0 + 0.5 * w, 1.6, 2.4);
  }
  for (const int w : {1, 3}) {  // short walls: shelves, posters and a door
    addShelf(scene, walls[w], 2.0, 1.8, 2.1);
    addPoster(scene, walls[w], 5.0, 1.1, 1.5, 1.0, true);
    addDoor(scene, walls[w], 8.5, 1.8, 2.6);
    addPoster(scene, walls[w], 12.0, 1.3, 0.8, 1.1, false);
    addShelf(scene, walls[w], 15.0, 1.6, 2.0);
  }
  const int concrete = scene.texture(TextureKind::kNoise, 0.65, 0.4, 0.6, 0.05);
  const int beam = scene.texture(TextureKind::kPlain, 0.6, 0.4, 1.0, 0.03);
  for (double x = 6.0; x < length - 1.0; x += 6.0) addPillar(scene, {x, 0.5 * width}, 0.6, height, concrete);
  for (double x = 3.0; x < length; x += 6.0)
    scene.box(Eigen::Vector3d(x, 0.5 * width, height - 0.25), Eigen::Matrix3d::Identity(), {0.15, 0.5 * width, 0.25},
              beam);
  addCeilingLights(scene, {4.5, 3.0}, {25.5, 17.0}, 3.5, height - 0.5);
  addBoxStack(scene, {1.2, 6.0}, 0.1, 3);
  addBoxStack(scene, {28.8, 13.0}, -0.2, 2);
  addDesk(scene, {15.0, 18.9}, 0.0);
  addDesk(scene, {15.0, 10.0}, M_PI / 2);

  SceneSetup setup;
  // A rounded rectangle around the row of pillars, waypoints about 4 m apart.
  const std::vector<Eigen::Vector2d> corners{{4.0, 4.5}, {26.0, 4.5}, {26.0, 15.5}, {4.0, 15.5}};
  for (int c = 0; c < 4; ++c) {
    const Eigen::Vector2d a = corners[c], b = corners[(c + 1) % 4];
    const int steps = static_cast<int>(std::round((b - a).norm() / 4.0));
    for (int k = 0; k < steps; ++k) {
      const Eigen::Vector2d jitter(scene.rng().uniform(-0.2, 0.2), scene.rng().uniform(-0.2, 0.2));
      setup.path.waypoints.push_back(a + (b - a) * (k + 0.5) / steps + jitter);
    }
  }
  setup.path.max_speed = 1.0;
  setup.path.max_turn_rate = 0.5;
  setup.path.acceleration = 0.5;
  setup.path.shake_deg = 0.4;
  setup.day = indoorDay();
  setup.night = indoorNight();
  setup.exposure = 0.015;
  setup.blur_by_default = true;
  setup.person.from = {5.0, 8.0};
  setup.person.to = {25.0, 8.0};
  // Lengthwise either side of the pillars, crosswise between them (x 9 and 21).
  for (const double y : {2.5, 7.0, 13.0, 17.5}) setup.lanes.push_back({{2.5, y}, {27.5, y}});
  for (const double x : {3.0, 9.0, 21.0, 27.0}) setup.lanes.push_back({{x, 1.8}, {x, 18.2}});
  return setup;
}

}  // namespace lvslam::sim
