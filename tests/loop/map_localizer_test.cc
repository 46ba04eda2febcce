// Localisation in a saved map, in the simulator's twin rooms (two identical
// offices along a corridor): a later drive is placed in a map of the first
// lap at its true pose, confirmed only by matches that agree, never through
// a room the map holds twice; a map of another place never localises it.
#include <cmath>

#include <gtest/gtest.h>

#include "loop/loop_scenes.h"
#include "lvslam/core/se3.h"
#include "lvslam/loop/map_localizer.h"
#include "lvslam/sim/lidar_simulator.h"
#include "lvslam/sim/scenario.h"

namespace lvslam::loop {
namespace {

constexpr double kDegree = M_PI / 180.0;

// Keyframes a metre apart over [t_begin, t_end): the features, and the pose
// `pose(T_world_lidar, path)` gives them.
template <typename Pose>
std::vector<LoopKeyframe> keyframesOver(const sim::Scenario& scenario, const sim::LidarSimulator& lidar,
                                        double t_begin, double t_end, Pose pose) {
  std::vector<LoopKeyframe> keyframes;
  double path = 0.0;
  Eigen::Vector3d last = scenario.T_world_lidar(t_begin).translation();
  for (double t = t_begin; t < t_end; t += 0.1) {
    const Eigen::Isometry3d T_world_lidar = scenario.T_world_lidar(t);
    if (t > t_begin && (T_world_lidar.translation() - last).norm() < 1.0) continue;
    path += (T_world_lidar.translation() - last).norm();
    last = T_world_lidar.translation();
    keyframes.push_back({t, pose(T_world_lidar, path), testing::keyframeFeatures(scenario, lidar, t), path});
  }
  return keyframes;
}

sim::SimOptions twinOptions() {
  sim::SimOptions options;
  options.duration = 270.0;
  return options;
}

// The simulator's LiDAR holds on to its scenario: both made in place.
struct TwinDrive {
  sim::Scenario scenario = sim::makeScenario("twins", twinOptions());
  sim::LidarSimulator lidar{scenario};
};

TEST(MapLocalizer, ALaterDriveIsPlacedInTheMapOfTheFirstLapAtItsTruePose) {
  const TwinDrive drive;
  // The map: the first lap (room A, the corridor, room B, back), at the true poses.
  const auto truth = [](const Eigen::Isometry3d& T_world_lidar, double) { return T_world_lidar; };
  MapLocalizer localizer(keyframesOver(drive.scenario, drive.lidar, 0.0, 138.0, truth), LoopClosureConfig{},
                         lidar::RegistrationConfig{});
  // The run: from 150 s, its odometry frame at its first pose, drifting
  // 0.3 % of its path along x and 0.02 deg per metre in yaw.
  const double t_start = 150.0;
  const Eigen::Isometry3d T_world_start = drive.scenario.T_world_lidar(t_start);
  const auto odometry = [&](const Eigen::Isometry3d& T_world_lidar, double path) {
    const Eigen::Isometry3d drift = makePose(
        Eigen::Matrix3d(Eigen::AngleAxisd(0.02 * kDegree * path, Eigen::Vector3d::UnitZ())),
        Eigen::Vector3d(0.003 * path, 0.0, 0.0));
    return drift * T_world_start.inverse() * T_world_lidar;
  };
  const std::vector<LoopKeyframe> run = keyframesOver(drive.scenario, drive.lidar, t_start, 270.0, odometry);
  int ambiguous = 0;
  for (const LoopKeyframe& kf : run) {
    localizer.addKeyframe(kf);
    const MapLocalization& r = localizer.result();
    if (!r.matches.empty() && r.matches.back().query_t == kf.t &&
        r.matches.back().reason.rfind("ambiguous", 0) == 0)
      ++ambiguous;
  }
  const MapLocalization& result = localizer.result();
  ASSERT_TRUE(result.T_map_odom.has_value()) << "never localised in " << result.matches.size() << " tries";
  // The true T_map_odom is the run's first pose; the first match is made
  // before the odometry has drifted more than a few centimetres.
  const Eigen::Isometry3d error = T_world_start.inverse() * *result.T_map_odom;
  EXPECT_LT(error.translation().norm(), 0.05);
  EXPECT_LT(rotationAngle(error) / kDegree, 0.5);
  EXPECT_LT(result.localized_t, t_start + 60.0);
  EXPECT_GE(result.agreeing, 3);
  // Every match taken is at the query's true place.
  for (const MapMatchRecord& m : result.matches) {
    if (!m.verified || !m.reason.empty()) continue;
    const Eigen::Isometry3d T_map_query = m.T_map_odom * run[static_cast<std::size_t>(m.query)].T_odom_lidar;
    EXPECT_LT((T_map_query.translation() - drive.scenario.T_world_lidar(m.query_t).translation()).norm(), 0.1)
        << "t " << m.query_t;
  }
  // In the rooms the scan fits both twins of the map.
  EXPECT_GE(ambiguous, 1);
}

TEST(MapLocalizer, AMapOfAnotherPlaceNeverLocalisesTheRun) {
  const TwinDrive drive;
  const testing::SyntheticScene store = testing::storeRoom();
  std::vector<LoopKeyframe> map;
  for (int k = 0; k < 12; ++k) {
    const Eigen::Isometry3d T_world_lidar =
        makePose(Eigen::Matrix3d(Eigen::AngleAxisd(0.5 * k, Eigen::Vector3d::UnitZ())),
                 Eigen::Vector3d(-5.0 + 0.8 * k, -1.5 + 0.2 * k, 0.95));
    map.push_back({static_cast<double>(k), T_world_lidar, testing::keyframeFeatures(store, T_world_lidar), 1.0 * k});
  }
  MapLocalizer localizer(std::move(map), LoopClosureConfig{}, lidar::RegistrationConfig{});
  const auto truth = [](const Eigen::Isometry3d& T_world_lidar, double) { return T_world_lidar; };
  for (const LoopKeyframe& kf : keyframesOver(drive.scenario, drive.lidar, 0.0, 138.0, truth))
    localizer.addKeyframe(kf);
  EXPECT_FALSE(localizer.result().T_map_odom.has_value());
  EXPECT_FALSE(localizer.result().matches.empty());
}

}  // namespace
}  // namespace lvslam::loop
