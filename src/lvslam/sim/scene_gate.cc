#include <cmath>

#include "lvslam/sim/indoor_parts.h"
#include "lvslam/sim/outdoor_parts.h"
#include "lvslam/sim/scene_setups.h"

namespace lvslam::sim {

namespace {

const std::vector<Eigen::Vector2d> kLampPosts{{-2.0, -4.0}, {-2.0, 5.0}, {9.0, 12.0}, {17.0, 12.0},
                                              {25.5, 0.0},  {9.0, -12.0}, {17.0, -12.0}};
constexpr double kLampHeight = 4.5;

Lighting outdoorNight() {
  Lighting light = outdoorDark();
  for (const auto& xy : kLampPosts) light.lamps.push_back({Eigen::Vector3d(xy.x(), xy.y(), kLampHeight - 0.1), 6.0});
  return light;
}

}  // namespace

Lighting outdoorDay() {
  Lighting light;
  light.ambient = 0.4;
  light.toward_light = Eigen::Vector3d(0.5, -0.35, 0.8).normalized();
  light.directional = 0.7;
  light.sky = 1.4;
  return light;
}

Lighting outdoorDark() {
  Lighting light = outdoorDay();
  light.ambient = 0.03;
  light.directional = 0.0;
  light.sky = 0.03;
  return light;
}

SceneSetup outdoorSetup(const Eigen::Vector2d& walk_from, const Eigen::Vector2d& walk_to) {
  SceneSetup setup;
  setDrive(setup.path, 1.0, 0.5, 0.5);
  setup.path.shake_deg = 0.5;
  setup.path.shake_height = 0.005;
  setup.day = outdoorDay();
  setup.night = outdoorDark();
  setup.exposure = 0.008;
  setup.person.from = walk_from;
  setup.person.to = walk_to;
  return setup;
}

SceneSetup buildGateScene(SceneBuilder& scene) {
  // A paved campus with an asphalt road through the gate.
  const int paving = scene.texture(TextureKind::kTiles, 0.5, 0.25, 0.5, 0.08);
  const int asphalt = scene.texture(TextureKind::kNoise, 0.3, 0.2, 0.08, 0.04);
  scene.rect(Eigen::Vector3d(0, 0, 0), Eigen::Matrix3d::Identity(), 120.0, 120.0, paving);
  scene.rect(Eigen::Vector3d(0, -16, 0.002), Eigen::Matrix3d::Identity(), 3.0, 14.0, asphalt);
  addBuilding(scene, WallFrame{{-30, 24, 0}, {1, 0, 0}, {0, -1, 0}, 60.0, 13.0}, 14.0, 4);
  addBuilding(scene, WallFrame{{-26, -30, 0}, {0, 1, 0}, {1, 0, 0}, 50.0, 10.0}, 12.0, 3);
  addBuilding(scene, WallFrame{{30, -40, 0}, {-1, 0, 0}, {0, 1, 0}, 50.0, 8.0}, 12.0, 2);
  addBuilding(scene, WallFrame{{42, 20, 0}, {0, -1, 0}, {-1, 0, 0}, 45.0, 11.0}, 12.0, 3);
  addGate(scene, {0.0, 0.0}, 0.0, 5.0, 25.0, 12.0);
  for (const Eigen::Vector2d& xy : {Eigen::Vector2d(-5, 4), Eigen::Vector2d(-5, 13), Eigen::Vector2d(5, 15),
                                    Eigen::Vector2d(13, 15), Eigen::Vector2d(28, 5), Eigen::Vector2d(28, -6),
                                    Eigen::Vector2d(13, -15), Eigen::Vector2d(4, -15), Eigen::Vector2d(-6, -7),
                                    Eigen::Vector2d(11, 3.5), Eigen::Vector2d(11, -3.5)})
    addTree(scene, xy);
  for (const auto& xy : kLampPosts) addLampPost(scene, xy, kLampHeight);
  addKerb(scene, {-3.0, -30.0}, {-3.0, -1.0});
  addKerb(scene, {-3.0, 1.0}, {-3.0, 20.0});
  addKerb(scene, {3.0, -12.5}, {20.0, -12.5});
  addKerb(scene, {20.0, 12.5}, {3.0, 12.5});
  addKerb(scene, {24.5, -10.0}, {24.5, 10.0});
  const int car = scene.texture(TextureKind::kPlain, 0.5, 0.1, 1.0, 0.05);
  for (const Eigen::Vector2d& xy : {Eigen::Vector2d(-8, -12), Eigen::Vector2d(-14, -12), Eigen::Vector2d(8, 19)}) {
    scene.uprightBox(xy, M_PI / 2, {4.2, 1.8, 0.8}, 0.2, car);
    scene.uprightBox(xy, M_PI / 2, {2.2, 1.6, 0.55}, 1.0, car);
  }

  SceneSetup setup = outdoorSetup({-8.5, -4.0}, {-8.5, 10.0});
  // A loop that passes through the gate and round the end of the fence.
  for (const Eigen::Vector2d& xy :
       {Eigen::Vector2d(0, -6), Eigen::Vector2d(0, -2), Eigen::Vector2d(0, 2), Eigen::Vector2d(0, 6),
        Eigen::Vector2d(3, 9.5), Eigen::Vector2d(7, 10), Eigen::Vector2d(11, 10), Eigen::Vector2d(15, 10),
        Eigen::Vector2d(19, 9.5), Eigen::Vector2d(22, 6), Eigen::Vector2d(22, 2), Eigen::Vector2d(22, -2),
        Eigen::Vector2d(22, -6), Eigen::Vector2d(19, -9.5), Eigen::Vector2d(15, -10), Eigen::Vector2d(11, -10),
        Eigen::Vector2d(7, -10), Eigen::Vector2d(3, -9.5)})
    setup.path.waypoints.push_back(xy + Eigen::Vector2d(scene.rng().uniform(-0.15, 0.15), 0.0));
  setup.night = outdoorNight();  // the street lamps are lit
  return setup;
}

}  // namespace lvslam::sim
