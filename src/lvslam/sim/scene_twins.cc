#include <cmath>
#include <initializer_list>
#include <utility>
#include <vector>

#include "lvslam/sim/indoor_parts.h"
#include "lvslam/sim/scene_setups.h"

namespace lvslam::sim {

namespace {

// Room A is [0, 10] x [0, 8]; room B is the same room moved 14 m along x.
// Both open through their north wall onto one corridor (y in [8, 10.4]).
constexpr double kRoomX = 10.0, kRoomY = 8.0, kHeight = 3.0;
constexpr double kTwinShift = 14.0;
constexpr double kOpeningFrom = 4.2, kOpeningTo = 5.8, kOpeningTop = 2.2;  // along the north wall, both faces
constexpr double kCorridorWidth = 2.4, kCorridorFrom = -3.0, kCorridorTo = 27.0;

// A wall rectangle over [s0, s1] x [z0, z1] of `wall`.
void wallRect(SceneBuilder& scene, const WallFrame& wall, double s0, double s1, double z0, double z1, int texture) {
  scene.rect(wall.at(0.5 * (s0 + s1), 0.5 * (z0 + z1), 0.0), wall.axes(), 0.5 * (s1 - s0), 0.5 * (z1 - z0),
             texture);
}

// Jambs and head around the opening, on one face of the north wall.
void addOpeningFrame(SceneBuilder& scene, const WallFrame& face, int texture) {
  const double bar = 0.07, depth = 0.04;
  scene.wallBox(face, kOpeningFrom - bar, 0.0, {bar, kOpeningTop + bar, depth}, texture);
  scene.wallBox(face, kOpeningTo, 0.0, {bar, kOpeningTop + bar, depth}, texture);
  scene.wallBox(face, kOpeningFrom - bar, kOpeningTop, {kOpeningTo - kOpeningFrom + 2 * bar, bar, depth}, texture);
}

// One office with its opening: floor, ceiling, walls, furniture. Everything
// random in it is drawn here, so a shifted copy of its primitives is its twin.
void addOffice(SceneBuilder& scene, const ShellStyle& style) {
  const Eigen::Vector3d centre(0.5 * kRoomX, 0.5 * kRoomY, 0.0);
  scene.rect(centre, Eigen::Matrix3d::Identity(), 0.5 * kRoomX, 0.5 * kRoomY, style.floor);
  scene.rect(centre + kHeight * Eigen::Vector3d::UnitZ(), Eigen::Matrix3d::Identity(), 0.5 * kRoomX, 0.5 * kRoomY,
             style.ceiling);
  const WallFrame south{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, kRoomX, kHeight};
  const WallFrame east{{kRoomX, 0, 0}, {0, 1, 0}, {-1, 0, 0}, kRoomY, kHeight};
  const WallFrame north{{kRoomX, kRoomY, 0}, {-1, 0, 0}, {0, -1, 0}, kRoomX, kHeight};
  const WallFrame west{{0, kRoomY, 0}, {0, -1, 0}, {1, 0, 0}, kRoomY, kHeight};
  const WallFrame north_outside{{0, kRoomY, 0}, {1, 0, 0}, {0, 1, 0}, kRoomX, kHeight};
  for (const WallFrame* wall : {&south, &east, &west}) {
    wallRect(scene, *wall, 0.0, wall->length, 0.0, kHeight, style.wall);
    scene.wallBox(*wall, 0.02, 0.0, {wall->length - 0.04, 0.09, 0.015}, style.baseboard);
  }
  // The opening is symmetric about the wall's middle, so s is the same from both faces.
  wallRect(scene, north, 0.0, kOpeningFrom, 0.0, kHeight, style.wall);
  wallRect(scene, north, kOpeningTo, kRoomX, 0.0, kHeight, style.wall);
  wallRect(scene, north, kOpeningFrom, kOpeningTo, kOpeningTop, kHeight, style.wall);
  scene.wallBox(north, 0.02, 0.0, {kOpeningFrom - 0.09, 0.09, 0.015}, style.baseboard);
  scene.wallBox(north, kOpeningTo + 0.07, 0.0, {kRoomX - kOpeningTo - 0.09, 0.09, 0.015}, style.baseboard);
  const int frame = scene.texture(TextureKind::kPlain, 0.3, 0.1, 0.5, 0.02);
  addOpeningFrame(scene, north, frame);
  addOpeningFrame(scene, north_outside, frame);

  addPoster(scene, south, 0.9, 1.2, 0.7, 1.0, true);
  addShelf(scene, south, 2.2, 1.6, 1.9);
  addWindow(scene, south, 5.0, 0.9, 1.8, 1.4);
  addDoor(scene, south, 8.6, 0.9, 2.1);
  addWindow(scene, east, 1.0, 0.9, 1.8, 1.4);
  addPoster(scene, east, 3.6, 1.2, 1.0, 0.7, false);
  addShelf(scene, east, 5.2, 1.4, 2.0);
  addShelf(scene, north, 0.4, 1.4, 1.8);
  addPoster(scene, north, 2.3, 1.1, 0.8, 1.1, true);
  addWindow(scene, north, 6.6, 0.9, 1.6, 1.4);
  addPoster(scene, north, 8.7, 1.4, 0.6, 0.8, true);
  addPoster(scene, west, 0.8, 0.9, 1.6, 1.0, true);
  addWindow(scene, west, 3.4, 0.9, 1.6, 1.4);
  addShelf(scene, west, 5.6, 1.4, 1.9);
  addDesk(scene, {5.0, 4.0}, 0.1);
  addDesk(scene, {8.2, 0.75}, M_PI);
  addDesk(scene, {1.6, 7.2}, 0.0);
  addBoxStack(scene, {9.3, 3.9}, 0.2, 3);
  addBoxStack(scene, {0.7, 0.8}, -0.1, 2);
  addBoxStack(scene, {7.2, 7.4}, 0.4, 2);
  addCeilingLights(scene, {2.0, 2.0}, {8.0, 6.0}, 2.0, kHeight);
}

// The corridor along both rooms' north walls; its own walls carry doors and
// notice boards at irregular places, so it does not repeat.
void addCorridor(SceneBuilder& scene, const ShellStyle& style) {
  const double length = kCorridorTo - kCorridorFrom, y0 = kRoomY, y1 = kRoomY + kCorridorWidth;
  const Eigen::Vector3d centre(0.5 * (kCorridorFrom + kCorridorTo), 0.5 * (y0 + y1), 0.0);
  scene.rect(centre, Eigen::Matrix3d::Identity(), 0.5 * length, 0.5 * kCorridorWidth, style.floor);
  scene.rect(centre + kHeight * Eigen::Vector3d::UnitZ(), Eigen::Matrix3d::Identity(), 0.5 * length,
             0.5 * kCorridorWidth, style.ceiling);
  const WallFrame north{{kCorridorTo, y1, 0}, {-1, 0, 0}, {0, -1, 0}, length, kHeight};
  const WallFrame south{{kCorridorFrom, y0, 0}, {1, 0, 0}, {0, 1, 0}, length, kHeight};
  const WallFrame west_end{{kCorridorFrom, y1, 0}, {0, -1, 0}, {1, 0, 0}, kCorridorWidth, kHeight};
  const WallFrame east_end{{kCorridorTo, y0, 0}, {0, 1, 0}, {-1, 0, 0}, kCorridorWidth, kHeight};
  for (const WallFrame* wall : {&north, &west_end, &east_end}) {
    wallRect(scene, *wall, 0.0, wall->length, 0.0, kHeight, style.wall);
    scene.wallBox(*wall, 0.02, 0.0, {wall->length - 0.04, 0.09, 0.015}, style.baseboard);
  }
  // The south side between and beyond the rooms (their north walls are the rest).
  const double room_b_end = kTwinShift + kRoomX;
  for (const auto& [x0, x1] : {std::pair{kCorridorFrom, 0.0}, std::pair{kRoomX, kTwinShift},
                               std::pair{room_b_end, kCorridorTo}})
    wallRect(scene, south, x0 - kCorridorFrom, x1 - kCorridorFrom, 0.0, kHeight, style.wall);
  for (const double s : {1.5, 7.5, 19.0, 26.5}) addDoor(scene, north, s, 0.9, 2.1);
  addPoster(scene, north, 4.0, 1.0, 1.2, 0.9, true);
  addPoster(scene, north, 10.0, 1.2, 1.0, 0.7, false);
  addPoster(scene, north, 13.2, 0.9, 1.4, 1.0, true);
  addPoster(scene, north, 15.5, 1.3, 0.8, 1.1, false);
  addPoster(scene, north, 22.0, 1.0, 1.4, 0.8, true);
  addPoster(scene, south, 1.0, 1.1, 1.0, 0.8, false);
  addPoster(scene, south, 14.0, 1.0, 1.0, 1.2, true);
  addCeilingLights(scene, {kCorridorFrom + 1.5, 0.5 * (y0 + y1)}, {kCorridorTo - 1.5, 0.5 * (y0 + y1)}, 3.0,
                   kHeight);
}

// A lap through room A (counter-clockwise about its middle desk), east along
// the corridor, the same lap in room B, and back west along the corridor.
void addTwinsLap(PathConfig& path) {
  // In through the opening at x 4.75, out at x 5.25 (room A's coordinates).
  const std::vector<Eigen::Vector2d> room_lap{{4.8, 7.3}, {3.5, 6.2}, {2.3, 4.8}, {2.3, 3.2}, {3.4, 2.0},
                                              {5.0, 1.6}, {6.6, 1.9}, {7.7, 3.0}, {7.8, 4.6}, {6.9, 5.8},
                                              {5.6, 6.6}, {5.25, 7.6}};
  const Eigen::Vector2d shift(kTwinShift, 0.0);
  const auto add = [&path](std::initializer_list<Eigen::Vector2d> points) {
    path.waypoints.insert(path.waypoints.end(), points.begin(), points.end());
  };
  for (const auto& p : room_lap) path.waypoints.push_back(p);
  add({{5.7, 8.7}, {6.9, 9.2}, {8.6, 9.2}, {10.5, 9.2}, {12.5, 9.2}, {14.5, 9.2}, {16.4, 9.2}, {17.9, 9.2},
       {18.7, 8.5}});
  for (const auto& p : room_lap) path.waypoints.push_back(p + shift);
  add({{19.0, 8.7}, {18.2, 9.75}, {16.6, 9.75}, {14.6, 9.75}, {12.6, 9.75}, {10.6, 9.75}, {8.6, 9.75},
       {6.8, 9.75}, {5.4, 9.3}, {4.9, 8.4}});
}

}  // namespace

SceneSetup buildTwinsScene(SceneBuilder& scene) {
  const ShellStyle style{scene.texture(TextureKind::kTiles, 0.55, 0.2, 0.6, 0.04),
                         scene.texture(TextureKind::kTiles, 0.85, 0.55, 0.6, 0.02),
                         scene.texture(TextureKind::kPlain, 0.75, 0.6, 1.0, 0.05),
                         scene.texture(TextureKind::kPlain, 0.2, 0.1, 1.0, 0.02)};
  const std::size_t room_a = scene.primitiveCount();
  addOffice(scene, style);
  scene.repeatShifted(room_a, Eigen::Vector3d(kTwinShift, 0.0, 0.0));
  addCorridor(scene, style);

  SceneSetup setup = indoorSetup(0.012, {1.0, 9.2}, {23.0, 9.2});
  addTwinsLap(setup.path);
  setDrive(setup.path, 0.5, 0.45, 0.25);
  return setup;
}

}  // namespace lvslam::sim
