#include "lvslam/sim/indoor_parts.h"

namespace lvslam::sim {

namespace {

const Eigen::Vector3d kUp = Eigen::Vector3d::UnitZ();

// A frame of four bars around an opening [s, s + w] x [z, z + h] on a wall,
// `bar` wide and `depth` proud of it.
void addFrame(SceneBuilder& scene, const WallFrame& wall, double s, double z, double w, double h, double bar,
              double depth, int texture, bool with_bottom) {
  scene.wallBox(wall, s - bar, z, {bar, h + bar, depth}, texture);
  scene.wallBox(wall, s + w, z, {bar, h + bar, depth}, texture);
  scene.wallBox(wall, s - bar, z + h, {w + 2 * bar, bar, depth}, texture);
  if (with_bottom) scene.wallBox(wall, s - bar, z - bar, {w + 2 * bar, bar, depth}, texture);
}

}  // namespace

std::array<WallFrame, 4> addRoomShell(SceneBuilder& scene, double size_x, double size_y, double height,
                                      const ShellStyle& style) {
  const Eigen::Vector3d centre(0.5 * size_x, 0.5 * size_y, 0.0);
  scene.rect(centre, Eigen::Matrix3d::Identity(), 0.5 * size_x, 0.5 * size_y, style.floor);
  scene.rect(centre + height * kUp, Eigen::Matrix3d::Identity(), 0.5 * size_x, 0.5 * size_y, style.ceiling);
  const std::array<WallFrame, 4> walls{
      WallFrame{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, size_x, height},
      WallFrame{{size_x, 0, 0}, {0, 1, 0}, {-1, 0, 0}, size_y, height},
      WallFrame{{size_x, size_y, 0}, {-1, 0, 0}, {0, -1, 0}, size_x, height},
      WallFrame{{0, size_y, 0}, {0, -1, 0}, {1, 0, 0}, size_y, height}};
  for (const WallFrame& wall : walls) {
    scene.rect(wall.at(0.5 * wall.length, 0.5 * height, 0.0), wall.axes(), 0.5 * wall.length, 0.5 * height,
               style.wall);
    // Baseboards stop short of the corners so neighbours do not overlap.
    scene.wallBox(wall, 0.02, 0.0, {wall.length - 0.04, 0.09, 0.015}, style.baseboard);
  }
  return walls;
}

void addDoor(SceneBuilder& scene, const WallFrame& wall, double s, double width, double height) {
  const int leaf = scene.texture(TextureKind::kPlanks, scene.rng().uniform(0.35, 0.7), 0.15, 0.3, 0.03);
  const int frame = scene.texture(TextureKind::kPlain, scene.rng().uniform(0.1, 0.9), 0.1, 0.5, 0.02);
  const int metal = scene.texture(TextureKind::kPlain, 0.8, 0.2, 0.5, 0.0);
  scene.wallBox(wall, s, 0.0, {width, height, 0.02}, leaf);
  addFrame(scene, wall, s, 0.0, width, height, 0.07, 0.04, frame, false);
  scene.wallBox(wall, s + width - 0.15, 1.0, {0.11, 0.03, 0.07}, metal);  // handle
}

void addWindow(SceneBuilder& scene, const WallFrame& wall, double s, double z, double width, double height) {
  const int glass = scene.texture(TextureKind::kNoise, 0.12, 0.05, 1.5, 0.02);
  const int frame = scene.texture(TextureKind::kPlain, scene.rng().uniform(0.6, 0.95), 0.1, 0.5, 0.01);
  scene.rect(wall.at(s + 0.5 * width, z + 0.5 * height, 0.003), wall.axes(), 0.5 * width, 0.5 * height, glass);
  addFrame(scene, wall, s, z, width, height, 0.06, 0.05, frame, true);
  scene.wallBox(wall, s + 0.5 * width - 0.02, z, {0.04, height, 0.03}, frame);   // mullion
  scene.wallBox(wall, s, z + 0.6 * height, {width, 0.04, 0.03}, frame);          // transom
  scene.wallBox(wall, s - 0.1, z - 0.1, {width + 0.2, 0.04, 0.14}, frame);       // sill
}

void addPoster(SceneBuilder& scene, const WallFrame& wall, double s, double z, double width, double height,
               bool framed) {
  const int paper = scene.texture(TextureKind::kPoster, scene.rng().uniform(0.75, 0.95),
                                  scene.rng().uniform(0.05, 0.3), scene.rng().uniform(0.06, 0.14), 0.02);
  scene.rect(wall.at(s + 0.5 * width, z + 0.5 * height, 0.004), wall.axes(), 0.5 * width, 0.5 * height, paper);
  if (!framed) return;
  const int frame = scene.texture(TextureKind::kPlain, scene.rng().uniform(0.05, 0.3), 0.1, 0.5, 0.01);
  addFrame(scene, wall, s, z, width, height, 0.03, 0.025, frame, true);
}

void addShelf(SceneBuilder& scene, const WallFrame& wall, double s, double width, double height) {
  const double depth = 0.35, board = 0.025;
  const int wood = scene.texture(TextureKind::kPlanks, scene.rng().uniform(0.3, 0.6), 0.15, 0.2, 0.03);
  scene.wallBox(wall, s, 0.0, {board, height, depth}, wood);
  scene.wallBox(wall, s + width - board, 0.0, {board, height, depth}, wood);
  scene.rect(wall.at(s + 0.5 * width, 0.5 * height, 0.005), wall.axes(), 0.5 * width - board, 0.5 * height, wood);
  const int levels = static_cast<int>(height / 0.38);
  const double gap = (height - board) / levels;
  for (int level = 0; level <= levels; ++level) {
    const double z = level * gap;
    scene.wallBox(wall, s + board, z, {width - 2 * board, board, depth}, wood);
    if (level == levels) break;
    // Books: random widths and heights, each its own shade.
    for (double x = s + board + 0.01; x < s + width - board - 0.1;) {
      const double w = scene.rng().uniform(0.03, 0.08), h = scene.rng().uniform(0.6, 0.9) * (gap - board);
      const double d = scene.rng().uniform(0.2, 0.28);
      if (scene.rng().uniform() < 0.85) {
        const int cover = scene.texture(TextureKind::kPlain, scene.rng().uniform(0.05, 0.95), 0.1, 0.5, 0.02);
        scene.wallBox(wall, x, z + board, {w, h, d}, cover);
      }
      x += w + 0.002;
    }
  }
}

void addDesk(SceneBuilder& scene, const Eigen::Vector2d& xy, double yaw) {
  const Eigen::Matrix3d R = yawRotation(yaw);
  const Eigen::Vector2d ex = R.col(0).head<2>(), ey = R.col(1).head<2>();
  const int top = scene.texture(TextureKind::kPlanks, scene.rng().uniform(0.45, 0.8), 0.3, 0.7, 0.03);
  const int metal = scene.texture(TextureKind::kPlain, 0.25, 0.1, 0.5, 0.02);
  const int screen = scene.texture(TextureKind::kPoster, 0.15, 0.05, 0.08, 0.01);
  scene.uprightBox(xy, yaw, {1.4, 0.7, 0.03}, 0.72, top);
  for (const double sx : {-0.65, 0.65})
    for (const double sy : {-0.3, 0.3}) scene.uprightBox(xy + sx * ex + sy * ey, yaw, {0.04, 0.04, 0.72}, 0.0, metal);
  scene.uprightBox(xy + 0.2 * ey, yaw, {0.56, 0.03, 0.34}, 0.9, screen);  // monitor
  scene.uprightBox(xy + 0.24 * ey, yaw, {0.05, 0.05, 0.15}, 0.75, metal); // its stand
  scene.uprightBox(xy - 0.12 * ey, yaw, {0.44, 0.14, 0.02}, 0.75, metal); // keyboard
}

void addBoxStack(SceneBuilder& scene, const Eigen::Vector2d& xy, double yaw, int count) {
  double z = 0.0;
  for (int i = 0; i < count; ++i) {
    const int cardboard = scene.texture(TextureKind::kNoise, scene.rng().uniform(0.35, 0.55), 0.2, 0.3, 0.05);
    const Eigen::Vector3d size(scene.rng().uniform(0.35, 0.6), scene.rng().uniform(0.3, 0.5),
                               scene.rng().uniform(0.25, 0.45));
    const Eigen::Vector2d jitter(scene.rng().uniform(-0.04, 0.04), scene.rng().uniform(-0.04, 0.04));
    scene.uprightBox(xy + jitter, yaw + scene.rng().uniform(-0.15, 0.15), size, z, cardboard);
    z += size.z();
  }
}

void addCeilingLights(SceneBuilder& scene, const Eigen::Vector2d& from, const Eigen::Vector2d& to, double spacing,
                      double height) {
  const int panel = scene.texture(TextureKind::kPlain, 1.0, 1.0, 1.0, 0.0);
  const int rim = scene.texture(TextureKind::kPlain, 0.45, 0.1, 1.0, 0.0);
  for (double x = from.x(); x <= to.x() + 1e-9; x += spacing)
    for (double y = from.y(); y <= to.y() + 1e-9; y += spacing) {
      scene.box(Eigen::Vector3d(x, y, height - 0.02), Eigen::Matrix3d::Identity(), {0.32, 0.32, 0.02}, rim);
      scene.rect(Eigen::Vector3d(x, y, height - 0.041), Eigen::Matrix3d::Identity(), 0.28, 0.28, panel);
    }
}

void addPillar(SceneBuilder& scene, const Eigen::Vector2d& xy, double side, double height, int texture) {
  const int band = scene.texture(TextureKind::kPlain, 0.15, 0.1, 1.0, 0.02);
  scene.uprightBox(xy, 0.0, {side, side, height}, 0.0, texture);
  scene.uprightBox(xy, 0.0, {side + 0.03, side + 0.03, 0.25}, 0.0, band);
}

}  // namespace lvslam::sim
