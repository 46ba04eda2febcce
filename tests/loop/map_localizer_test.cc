// Localisation in a saved map, in the simulator's twin rooms (two identical
// offices along a corridor): a later drive is placed in a map of the first
// lap at its true pose, confirmed only by matches that agree, never through
// a room the map holds twice; a map of another place never localises it.
#include <cmath>
#include <memory>

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
  options.duration = 420.0;  // three laps of about 138 s
  return options;
}

// The simulator's LiDAR holds on to its scenario: both made in place.
struct TwinDrive {
  sim::Scenario scenario = sim::makeScenario("twins", twinOptions());
  sim::LidarSimulator lidar{scenario};
};

constexpr double kLap = 138.0;  // seconds, about

struct Localised {
  MapLocalization result;
  std::vector<LoopKeyframe> run;
  Eigen::Isometry3d T_world_start;
  int ambiguous = 0;
};

// A map of the drive over [0, map_end) at the true poses, and the drive from
// t_start to t_end localised in it with an odometry that starts at its first
// pose and drifts 0.3 % of its path along x and 0.02 deg per metre in yaw.
Localised localise(const TwinDrive& drive, double map_end, double t_start, double t_end) {
  const auto truth = [](const Eigen::Isometry3d& T_world_lidar, double) { return T_world_lidar; };
  MapLocalizer localizer(
      std::make_shared<const std::vector<LoopKeyframe>>(keyframesOver(drive.scenario, drive.lidar, 0.0, map_end, truth)),
      LoopClosureConfig{}, lidar::RegistrationConfig{});
  Localised out;
  out.T_world_start = drive.scenario.T_world_lidar(t_start);
  const auto odometry = [&](const Eigen::Isometry3d& T_world_lidar, double path) {
    const Eigen::Isometry3d drift = makePose(
        Eigen::Matrix3d(Eigen::AngleAxisd(0.02 * kDegree * path, Eigen::Vector3d::UnitZ())),
        Eigen::Vector3d(0.003 * path, 0.0, 0.0));
    return drift * out.T_world_start.inverse() * T_world_lidar;
  };
  out.run = keyframesOver(drive.scenario, drive.lidar, t_start, t_end, odometry);
  for (const LoopKeyframe& kf : out.run) localizer.addKeyframe(kf);
  out.result = localizer.result();
  for (const MapMatchRecord& m : out.result.matches) out.ambiguous += m.reason.rfind("ambiguous", 0) == 0 ? 1 : 0;
  return out;
}

// Every match taken is at its query's true place.
void expectTakenMatchesAtTheTruePlace(const TwinDrive& drive, const Localised& l) {
  for (const MapMatchRecord& m : l.result.matches) {
    if (!m.verified || !m.reason.empty()) continue;
    const Eigen::Isometry3d T_map_query = m.T_map_odom * l.run[static_cast<std::size_t>(m.query)].T_odom_lidar;
    EXPECT_LT((T_map_query.translation() - drive.scenario.T_world_lidar(m.query_t).translation()).norm(), 0.1)
        << "t " << m.query_t;
  }
}

TEST(MapLocalizer, ALaterDriveIsPlacedInTheMapOfTheFirstLapAtItsTruePose) {
  const TwinDrive drive;
  const Localised l = localise(drive, kLap, 150.0, 270.0);
  ASSERT_TRUE(l.result.T_map_odom.has_value()) << "never localised in " << l.result.matches.size() << " tries";
  // The true T_map_odom is the run's first pose; the first match is made
  // before the odometry has drifted more than a few centimetres.
  const Eigen::Isometry3d error = l.T_world_start.inverse() * *l.result.T_map_odom;
  EXPECT_LT(error.translation().norm(), 0.05);
  EXPECT_LT(rotationAngle(error) / kDegree, 0.5);
  EXPECT_LT(l.result.localized_t, 150.0 + 60.0);
  EXPECT_GE(l.result.agreeing, 3);
  expectTakenMatchesAtTheTruePlace(drive, l);
  // In the rooms the scan fits both twins of the map.
  EXPECT_GE(l.ambiguous, 1);
}

// A map of two laps holds each place twice at the same pose: that is not
// an ambiguity, and the twin room further down the candidates still is.
TEST(MapLocalizer, AMapOfTwoLapsStillTellsTheSamePlaceFromItsTwin) {
  const TwinDrive drive;
  const Localised l = localise(drive, 2.0 * kLap, 2.0 * kLap + 12.0, 2.0 * kLap + 130.0);
  ASSERT_TRUE(l.result.T_map_odom.has_value()) << "never localised in " << l.result.matches.size() << " tries";
  const Eigen::Isometry3d error = l.T_world_start.inverse() * *l.result.T_map_odom;
  EXPECT_LT(error.translation().norm(), 0.05);
  EXPECT_LT(rotationAngle(error) / kDegree, 0.5);
  expectTakenMatchesAtTheTruePlace(drive, l);
  EXPECT_GE(l.ambiguous, 1);
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
  MapLocalizer localizer(std::make_shared<const std::vector<LoopKeyframe>>(std::move(map)), LoopClosureConfig{},
                         lidar::RegistrationConfig{});
  const auto truth = [](const Eigen::Isometry3d& T_world_lidar, double) { return T_world_lidar; };
  for (const LoopKeyframe& kf : keyframesOver(drive.scenario, drive.lidar, 0.0, 138.0, truth))
    localizer.addKeyframe(kf);
  EXPECT_FALSE(localizer.result().T_map_odom.has_value());
  EXPECT_FALSE(localizer.result().matches.empty());
}

}  // namespace
}  // namespace lvslam::loop
