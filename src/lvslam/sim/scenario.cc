#include "lvslam/sim/scenario.h"

#include <algorithm>

#include "lvslam/core/error.h"
#include "lvslam/core/se3.h"
#include "lvslam/sim/scene_setups.h"

namespace lvslam::sim {

namespace {

// Velodyne VLP-32C laser elevations (degrees), ascending.
const std::vector<double> kVlp32cElevations{
    -25.0,  -15.639, -11.31, -8.843, -7.254, -6.148, -5.333, -4.667, -4.0,   -3.667, -3.333,
    -3.0,   -2.667,  -2.333, -2.0,   -1.667, -1.333, -1.0,   -0.667, -0.333, 0.0,    0.333,
    0.667,  1.0,     1.333,  1.667,  2.333,  3.333,  4.667,  7.0,    10.333, 15.0};

// LiDAR on a mast, camera lower and forward; R_lidar_camera = [0 0 1; -1 0 0; 0 -1 0].
Rig makeRig() {
  Rig rig;
  rig.T_body_lidar = makePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, 0.95));
  Eigen::Matrix3d R_body_camera;
  R_body_camera << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  rig.T_body_camera = makePose(R_body_camera, Eigen::Vector3d(0.16, 0.025, 0.74));
  return rig;
}

// RealSense D435i colour camera as in M2DGR's calibration.
CameraConfig makeCamera(const SimOptions& options, const SceneSetup& setup) {
  CameraConfig camera;
  const RadTanDistortion distortion =
      options.distortion ? RadTanDistortion{0.12, -0.24, 0.0008, -0.0005, 0.0} : RadTanDistortion{};
  camera.camera = PinholeCamera(640, 480, 617.971, 616.445, 327.710, 253.976, distortion);
  camera.start_offset = 0.0127;
  camera.exposure = (options.night ? 3.0 * setup.exposure : setup.exposure) * options.exposure_scale;
  const bool blur = options.blur.value_or(setup.blur_by_default);
  camera.blur_samples = blur ? options.blur_samples : 1;
  // The D435i's colour sensor (OV2740) reads its rows out over about 24 ms.
  if (options.rolling_shutter) camera.line_time = 0.024 / camera.camera.height();
  camera.auto_exposure.enabled = options.auto_exposure;
  if (options.night) {  // gain at its limit: more read and shot noise
    camera.read_noise = 5.0;
    camera.shot_noise = 0.5;
  }
  return camera;
}

// Velodyne VLP-16 (Puck): 16 lasers from -15 to +15 deg, 2 deg apart.
std::vector<double> vlp16Elevations() {
  std::vector<double> elevations;
  for (int ring = 0; ring < 16; ++ring) elevations.push_back(-15.0 + 2.0 * ring);
  return elevations;
}

LidarConfig makeLidar(const SimOptions& options) {
  LidarConfig lidar;
  lidar.elevations_deg = options.lidar == "vlp16" ? vlp16Elevations() : kVlp32cElevations;
  lidar.start_offset = 0.0519;
  if (options.beam_footprint) {
    // Both Velodynes: 3 mrad divergence, about 3 cm accuracy at 20-50 m.
    lidar.beam.footprint = true;
    lidar.range_noise = 0.012;
    lidar.range_noise_per_metre = 0.0005;
    lidar.min_cos_incidence = 0.2;
  }
  return lidar;
}

SceneSetup buildScene(const std::string& name, SceneBuilder& scene) {
  if (name == "room") return buildRoomScene(scene);
  if (name == "hall") return buildHallScene(scene);
  if (name == "gate") return buildGateScene(scene);
  if (name == "corridor") return buildCorridorScene(scene);
  if (name == "yard") return buildYardScene(scene);
  if (name == "office") return buildOfficeScene(scene);
  if (name == "twins") return buildTwinsScene(scene);
  return buildAtriumScene(scene);
}

void scaleSpeed(PathConfig& path, double scale) {
  path.max_speed *= scale;
  path.max_turn_rate *= scale;
  path.acceleration *= scale;
}

// The walkers, each in its own clothes (textures added only when there are
// more than one, so scenes without a crowd keep their bytes).
std::vector<WalkingPerson> makeWalkers(const SimOptions& options, const SceneSetup& setup, int clothes,
                                       SceneBuilder& scene) {
  const int count = std::max(options.people, options.walking_person ? 1 : 0);
  std::vector<int> wardrobe{clothes};
  for (int i = 1; i < std::min(count, 6); ++i)
    wardrobe.push_back(scene.texture(TextureKind::kNoise, 0.1 + 0.13 * i, 0.1, 0.15, 0.05));
  if (count > 1 && setup.lanes.empty())
    throw Error("--people", "scenario '" + options.scenario + "' has no walking lanes for more than one person");
  return makePeople(setup.person, setup.lanes, count, wardrobe, options.seed);
}

}  // namespace

Scenario makeScenario(const SimOptions& options) {
  validate(options);
  SceneBuilder scene(options.seed);
  const int clothes = scene.texture(TextureKind::kNoise, 0.3, 0.1, 0.15, 0.05);
  SceneSetup setup = buildScene(options.scenario, scene);
  setup.path.duration = options.duration;
  scaleSpeed(setup.path, options.speed_scale);
  setup.person.texture = clothes;
  std::vector<WalkingPerson> people = makeWalkers(options, setup, clothes, scene);
  CameraConfig camera = makeCamera(options, setup);
  return Scenario{options.scenario,
                  options,
                  scene.build(),
                  RobotTrajectory(setup.path, options.seed),
                  makeRig(),
                  camera,
                  makeLidar(options),
                  options.night ? setup.night : setup.day,
                  std::move(people)};
}

Scenario makeScenario(const std::string& name, SimOptions options) {
  options.scenario = name;
  return makeScenario(options);
}

}  // namespace lvslam::sim
