#include "lvslam/system/offline/loop_on_fused.h"

#include <gtest/gtest.h>

namespace lvslam::system {
namespace {

Eigen::Isometry3d atX(double x) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation().x() = x;
  return T;
}

// Two keyframes 20 m of path apart, truly 0.3 m apart; the LiDAR odometry
// put the second 2.3 m from the first (2 m of drift), so the loop the ICP
// verified was refused on it. The fused trajectory is right: carried onto
// it, the keyframes are 0.3 m apart and the loop is taken.
TEST(LoopOnFused, KeyframesAreCarriedOntoTheFusedTrajectoryAndTheLoopGatedAgain) {
  const loop::LoopClosureConfig config;
  loop::LoopClosureResult live;
  live.keyframe_times = {0.0, 30.0};
  live.path_lengths = {0.0, 20.0};
  live.T_odom_lidar = {atX(0.0), atX(2.3)};
  live.T_odom_lidar_corrected = live.T_odom_lidar;
  loop::LoopCandidateRecord c;
  c.query = 1;
  c.candidate = 0;
  c.verified = true;
  c.verification.accepted = true;
  c.verification.T_candidate_query = atX(0.3);
  c.verification.information = Matrix6d::Identity() * 1e4;
  c.reason = "off the odometry by 2.00 m, 0.0 deg (> 0.67 m, 6.7 deg)";
  live.candidates = {c};
  // Camera poses (the camera is the LiDAR here) every 1/15 s, the drift
  // growing with time in the odometry only (the path out and back is not
  // drawn: only the poses at the keyframes' times matter).
  Trajectory refined, lidar_odometry;
  for (int j = 0; j <= 450; ++j) {
    const double t = j / 15.0;
    refined.push_back({t, atX(0.3 * t / 30.0)});
    lidar_odometry.push_back({t, atX(2.3 * t / 30.0)});
  }
  const auto fused = loopOnFusedTrajectory(live, refined, lidar_odometry, config);
  ASSERT_TRUE(fused);
  EXPECT_EQ(fused->odometry, "fused");
  EXPECT_NEAR(fused->T_odom_lidar[0].translation().x(), 0.0, 1e-9);
  EXPECT_NEAR(fused->T_odom_lidar[1].translation().x(), 0.3, 1e-9);
  EXPECT_EQ(fused->accepted(), 1u);
  EXPECT_EQ(live.accepted(), 0u);
  EXPECT_FALSE(loopOnFusedTrajectory(live, {}, lidar_odometry, config));
}

}  // namespace
}  // namespace lvslam::system
