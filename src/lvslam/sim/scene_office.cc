#include <cmath>

#include "lvslam/sim/indoor_parts.h"
#include "lvslam/sim/outdoor_parts.h"
#include "lvslam/sim/scene_setups.h"

namespace lvslam::sim {

namespace {

// A frameless glass wall (structural glazing): floor-to-ceiling panes butted
// together, held only by a channel at the floor and the ceiling and by a
// corner post at each end.
void addGlassWall(SceneBuilder& scene, const WallFrame& wall, double pane, int glass, int metal) {
  const int panes = static_cast<int>(std::round(wall.length / pane));
  const double w = wall.length / panes;
  for (int i = 0; i < panes; ++i)
    scene.glassPane(wall.at((i + 0.5) * w, 0.5 * wall.height, 0.0), wall.axes(), 0.5 * w, 0.5 * wall.height - 0.05,
                    glass);
  for (const double s : {0.0, wall.length - 0.06}) scene.wallBox(wall, s, 0.0, {0.06, wall.height, 0.06}, metal);
  scene.wallBox(wall, 0.0, 0.0, {wall.length, 0.05, 0.05}, metal);                 // floor channel
  scene.wallBox(wall, 0.0, wall.height - 0.05, {wall.length, 0.05, 0.05}, metal);  // ceiling channel
}

}  // namespace

SceneSetup buildOfficeScene(SceneBuilder& scene) {
  // White walls, plain floor and ceiling, plain furniture: the geometry of an
  // office with almost nothing for a corner detector.
  const ShellStyle style{scene.texture(TextureKind::kPlain, 0.45, 0.4, 1.0, 0.01),
                         scene.texture(TextureKind::kPlain, 0.85, 0.8, 1.0, 0.005),
                         scene.texture(TextureKind::kPlain, 0.8, 0.75, 1.0, 0.005),
                         scene.texture(TextureKind::kPlain, 0.7, 0.6, 1.0, 0.005)};
  addRoomShell(scene, 12.0, 9.0, 3.0, style);
  const int furniture = scene.texture(TextureKind::kPlain, 0.7, 0.6, 1.0, 0.005);
  const int cabinet = scene.texture(TextureKind::kPlain, 0.75, 0.7, 1.0, 0.005);
  for (const double x : {3.0, 6.0, 9.0}) {
    scene.uprightBox({x, 0.5}, 0.0, {1.6, 0.8, 0.75}, 0.0, furniture);      // desks along the south wall
    scene.uprightBox({x - 1.0, 8.7}, 0.0, {0.9, 0.5, 1.9}, 0.0, cabinet);  // cabinets along the north wall
  }
  scene.uprightBox({11.5, 4.5}, 0.0, {0.6, 2.4, 1.1}, 0.0, furniture);  // a sideboard on the east wall
  scene.uprightBox({6.0, 4.5}, 0.0, {0.5, 0.5, 3.0}, 0.0, cabinet);      // a pillar in the middle
  scene.uprightBox({0.4, 6.5}, 0.0, {0.8, 1.6, 1.2}, 0.0, cabinet);      // shelving on the west wall

  SceneSetup setup = indoorSetup(0.012, {2.0, 2.0}, {2.0, 7.0});
  addEllipseLoop(scene, setup.path, {6.0, 4.5}, 3.8, 2.4, 10, 0.06);
  setDrive(setup.path, 0.5, 0.45, 0.25);
  return setup;
}

SceneSetup buildAtriumScene(SceneBuilder& scene) {
  const double length = 24.0, width = 14.0, height = 4.5;
  const int floor = scene.texture(TextureKind::kTiles, 0.6, 0.35, 0.8, 0.04);
  const int ceiling = scene.texture(TextureKind::kPlain, 0.85, 0.6, 1.0, 0.02);
  const int glass = scene.texture(TextureKind::kPlain, 0.1, 0.1, 1.0, 0.0);
  const int metal = scene.texture(TextureKind::kPlain, 0.3, 0.1, 1.0, 0.02);
  const int wall = scene.texture(TextureKind::kPlain, 0.75, 0.6, 1.0, 0.03);
  const Eigen::Vector3d centre(0.5 * length, 0.5 * width, 0.0);
  // Outside: a paved square, trees and the buildings around it (seen through the glass).
  const int paving = scene.texture(TextureKind::kTiles, 0.5, 0.25, 0.5, 0.08);
  scene.rect(Eigen::Vector3d(0.5 * length, 0.0, -0.002), Eigen::Matrix3d::Identity(), 150.0, 150.0, paving);
  addBuilding(scene, WallFrame{{-20, -25, 0}, {1, 0, 0}, {0, 1, 0}, 64.0, 12.0}, 12.0, 3);
  addBuilding(scene, WallFrame{{-18, 30, 0}, {0, -1, 0}, {1, 0, 0}, 55.0, 12.0}, 12.0, 3);
  addBuilding(scene, WallFrame{{42, -25, 0}, {0, 1, 0}, {-1, 0, 0}, 55.0, 12.0}, 12.0, 3);
  for (double x = 2.0; x < length; x += 5.0) addTree(scene, {x, -8.0});
  scene.rect(centre + Eigen::Vector3d(0, 2.0, 0), Eigen::Matrix3d::Identity(), 0.5 * length, 0.5 * width + 2.0, floor);
  scene.rect(centre + Eigen::Vector3d(0, 2.0, height), Eigen::Matrix3d::Identity(), 0.5 * length,
             0.5 * width + 2.0, ceiling);
  // Glass on all four sides: the facade (south, to an open square), the
  // partitions of the meeting rooms (north) and the lobbies (east, west).
  const WallFrame south{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, length, height};
  const WallFrame east{{length, 0, 0}, {0, 1, 0}, {-1, 0, 0}, width, height};
  const WallFrame north{{length, width, 0}, {-1, 0, 0}, {0, -1, 0}, length, height};
  const WallFrame west{{0, width, 0}, {0, -1, 0}, {1, 0, 0}, width, height};
  addGlassWall(scene, south, 1.5, glass, metal);
  addGlassWall(scene, east, 1.4, glass, metal);
  addGlassWall(scene, north, 1.2, glass, metal);
  addGlassWall(scene, west, 1.4, glass, metal);
  // Behind the partitions: meeting rooms 4 m deep, their back wall with
  // posters and shelves, tables (seen through the glass).
  const WallFrame back{{length, width + 4.0, 0}, {-1, 0, 0}, {0, -1, 0}, length, height};
  scene.rect(back.at(0.5 * length, 0.5 * height, 0.0), back.axes(), 0.5 * length, 0.5 * height, wall);
  for (double s = 1.0; s + 3.0 < length; s += 4.0) {
    addPoster(scene, back, s, 1.0, 1.4, 1.0, true);
    addShelf(scene, back, s + 2.0, 1.2, 1.8);
  }
  for (double x = 3.0; x < length; x += 6.0) addDesk(scene, {x, width + 2.0}, 0.0);
  // Inside the atrium: two round pillars, a reception desk, planters.
  const int concrete = scene.texture(TextureKind::kNoise, 0.6, 0.4, 0.5, 0.05);
  scene.cylinder({8.0, 7.0}, 0.0, height, 0.35, concrete);
  scene.cylinder({16.0, 7.0}, 0.0, height, 0.35, concrete);
  addDesk(scene, {12.0, 7.0}, 0.0);
  const int pot = scene.texture(TextureKind::kNoise, 0.35, 0.2, 0.2, 0.05);
  const int leaves = scene.texture(TextureKind::kNoise, 0.25, 0.05, 0.1, 0.05);
  for (const Eigen::Vector2d& xy : {Eigen::Vector2d(3.0, 3.0), Eigen::Vector2d(21.0, 11.0)}) {
    scene.cylinder(xy, 0.0, 0.6, 0.3, pot);
    scene.sphere(Eigen::Vector3d(xy.x(), xy.y(), 1.1), 0.5, leaves);
  }

  SceneSetup setup = indoorSetup(0.010, {4.0, 4.0}, {20.0, 4.0});
  setup.day.sky = 1.2;  // daylight through the facade
  addEllipseLoop(scene, setup.path, {12.0, 7.0}, 8.0, 4.0, 12, 0.06);
  setDrive(setup.path, 0.8, 0.5, 0.4);
  return setup;
}

}  // namespace lvslam::sim
