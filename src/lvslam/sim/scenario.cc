#include "lvslam/sim/scenario.h"

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
  camera.exposure = options.night ? 3.0 * setup.exposure : setup.exposure;
  const bool blur = options.blur.value_or(setup.blur_by_default);
  camera.blur_samples = blur ? 5 : 1;
  if (options.night) {  // gain at its limit: more read and shot noise
    camera.read_noise = 5.0;
    camera.shot_noise = 0.5;
  }
  return camera;
}

LidarConfig makeLidar() {
  LidarConfig lidar;
  lidar.elevations_deg = kVlp32cElevations;
  lidar.start_offset = 0.0519;
  return lidar;
}

}  // namespace

Scenario makeScenario(const SimOptions& options) {
  validate(options);
  SceneBuilder scene(options.seed);
  const int clothes = scene.texture(TextureKind::kNoise, 0.3, 0.1, 0.15, 0.05);
  SceneSetup setup = options.scenario == "room"   ? buildRoomScene(scene)
                     : options.scenario == "hall" ? buildHallScene(scene)
                                                  : buildGateScene(scene);
  setup.path.duration = options.duration;
  setup.person.texture = clothes;
  return Scenario{options.scenario,
                  options,
                  scene.build(),
                  RobotTrajectory(setup.path, options.seed),
                  makeRig(),
                  makeCamera(options, setup),
                  makeLidar(),
                  options.night ? setup.night : setup.day,
                  options.walking_person ? std::optional<WalkingPerson>(setup.person) : std::nullopt};
}

Scenario makeScenario(const std::string& name, SimOptions options) {
  options.scenario = name;
  return makeScenario(options);
}

}  // namespace lvslam::sim
