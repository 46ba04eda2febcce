// Loop closure in the simulator's twin rooms (two identical offices along a
// corridor): room B passes Scan Context and the ICP as room A, and the
// odometry refuses it; the true return to room A closes a loop.
#include <cmath>

#include <gtest/gtest.h>

#include "loop/loop_scenes.h"
#include "lvslam/core/se3.h"
#include "lvslam/loop/loop_closure.h"
#include "lvslam/sim/lidar_simulator.h"
#include "lvslam/sim/scenario.h"

namespace lvslam::loop {
namespace {

double truthDistance(const sim::Scenario& scenario, const LoopCandidateRecord& c, double t0) {
  return (scenario.T_world_lidar(c.query_t - t0).translation() - scenario.T_world_lidar(c.candidate_t - t0).translation())
      .norm();
}

TEST(TwinRooms, TheSecondRoomRegistersAsTheFirstAndTheOdometryRefusesIt) {
  sim::SimOptions options;
  options.duration = 160.0;
  const sim::Scenario scenario = sim::makeScenario("twins", options);
  const sim::LidarSimulator lidar(scenario);
  // An odometry that drifts 0.3 % of its path along x and 0.02 deg per metre in yaw.
  const auto odometry = [](const Eigen::Isometry3d& T_world_lidar, double path) {
    const Eigen::Isometry3d drift =
        makePose(Eigen::Matrix3d(Eigen::AngleAxisd(0.02 * M_PI / 180.0 * path, Eigen::Vector3d::UnitZ())),
                 Eigen::Vector3d(0.003 * path, 0.0, 0.0));
    return drift * T_world_lidar;
  };
  LoopClosure closure{LoopClosureConfig{}, lidar::RegistrationConfig{}};
  const double t0 = options.start_time;
  double path = 0.0;
  Eigen::Vector3d last = scenario.T_world_lidar(0.0).translation();
  // A keyframe every metre of the lap (room A, corridor, room B, corridor)
  // and on into room A again.
  for (double t = 0.0; t < options.duration - 1.0; t += 0.1) {
    const Eigen::Isometry3d T_world_lidar = scenario.T_world_lidar(t);
    if (t > 0.0 && (T_world_lidar.translation() - last).norm() < 1.0) continue;
    path += (T_world_lidar.translation() - last).norm();
    last = T_world_lidar.translation();
    closure.addKeyframe({t0 + t, odometry(T_world_lidar, path), testing::keyframeFeatures(scenario, lidar, t), path});
  }
  int twins_registered = 0, twins_accepted = 0, revisits_accepted = 0;
  for (const LoopCandidateRecord& c : closure.candidates()) {
    const bool twin = truthDistance(scenario, c, t0) > 10.0;
    if (twin && c.verification.accepted) {
      ++twins_registered;
      EXPECT_EQ(c.reason.rfind("off the odometry by", 0), 0u) << c.reason;
    }
    if (c.reason.empty()) (twin ? twins_accepted : revisits_accepted) += 1;
  }
  EXPECT_GE(twins_registered, 3) << "room B should pass place recognition and the ICP as room A";
  EXPECT_EQ(twins_accepted, 0);
  EXPECT_GE(revisits_accepted, 1) << "the return to room A should close a loop";
}

}  // namespace
}  // namespace lvslam::loop
