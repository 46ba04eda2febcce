#pragma once
// Pieces of indoor scenes. Every line a camera sees on them is also in the
// geometry: frames stand a few centimetres proud of the walls, furniture is
// made of boxes, baseboards mark the wall-floor boundary.
#include <array>

#include "lvslam/sim/scene_builder.h"

namespace lvslam::sim {

struct ShellStyle {
  int floor, ceiling, wall, baseboard;
};

// Floor, ceiling and four walls of an axis-aligned room [0, size_x] x
// [0, size_y] x [0, height]; returns the walls (south, east, north, west).
std::array<WallFrame, 4> addRoomShell(SceneBuilder& scene, double size_x, double size_y, double height,
                                      const ShellStyle& style);

void addDoor(SceneBuilder& scene, const WallFrame& wall, double s, double width, double height);
void addWindow(SceneBuilder& scene, const WallFrame& wall, double s, double z, double width, double height);
// A poster (optionally in a picture frame) with its lower-left corner at s, z.
void addPoster(SceneBuilder& scene, const WallFrame& wall, double s, double z, double width, double height,
               bool framed);
// A bookshelf against the wall, filled with books of random sizes and shades.
void addShelf(SceneBuilder& scene, const WallFrame& wall, double s, double width, double height);
// A desk with a monitor; `yaw` turns it about its centre.
void addDesk(SceneBuilder& scene, const Eigen::Vector2d& xy, double yaw);
// A stack of cardboard boxes.
void addBoxStack(SceneBuilder& scene, const Eigen::Vector2d& xy, double yaw, int count);
// Bright ceiling light panels in a grid below a ceiling at `height`.
void addCeilingLights(SceneBuilder& scene, const Eigen::Vector2d& from, const Eigen::Vector2d& to, double spacing,
                      double height);
// A square pillar from floor to ceiling with a darker base band.
void addPillar(SceneBuilder& scene, const Eigen::Vector2d& xy, double side, double height, int texture);

}  // namespace lvslam::sim
