// LoopClosure over keyframes: a revisit after a lap closes a loop, while a
// place that looks and registers the same (a hall symmetric under a half
// turn) is refused because the odometry puts it 10 m away.
#include <cmath>

#include <gtest/gtest.h>

#include "loop/loop_scenes.h"
#include "lvslam/core/se3.h"
#include "lvslam/loop/loop_closure.h"

namespace lvslam::loop {
namespace {

// A 20 x 12 m hall with four pillars, the same seen from (-5, 0) facing +x
// and from (5, 0) facing -x.
testing::SyntheticScene symmetricHall() {
  testing::SyntheticScene s;
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(), z = Eigen::Vector3d::UnitZ();
  s.planes = {{z, 0.0}, {z, 4.0}, {x, -10.0}, {x, 10.0}, {y, -6.0}, {y, 6.0}};
  s.boxes = {{{-1, -3, 0}, {1, -2, 1.5}}, {{-1, 2, 0}, {1, 3, 1.5}}};
  s.poles = {{{-6, 3}, 0.3, 0, 4}, {{6, -3}, 0.3, 0, 4}, {{-3, -4}, 0.2, 0, 4}, {{3, 4}, 0.2, 0, 4}};
  return s;
}

Eigen::Isometry3d at(double x, double yaw) {
  return makePose(Eigen::Matrix3d(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ())), Eigen::Vector3d(x, 0.0, 1.0));
}

LoopKeyframe keyframe(const testing::SyntheticScene& scene, const Eigen::Isometry3d& T_world_lidar,
                      const Eigen::Isometry3d& T_odom_lidar, double t, double path) {
  return {t, T_odom_lidar, testing::keyframeFeatures(scene, T_world_lidar), path};
}

TEST(LoopClosure, ARevisitAfterALapClosesALoop) {
  const auto scene = symmetricHall();
  LoopClosure closure{LoopClosureConfig{}, lidar::RegistrationConfig{}};
  EXPECT_FALSE(closure.addKeyframe(keyframe(scene, at(-5, 0), at(-5, 0), 0.0, 0.0)));
  // 20 m of path later the robot is back, 0.3 m further on; its odometry drifted 0.1 m.
  EXPECT_TRUE(closure.addKeyframe(keyframe(scene, at(-4.7, 0), at(-4.6, 0), 30.0, 20.0)));
  const LoopClosureResult result = closure.solve();
  ASSERT_EQ(result.candidates.size(), 1u);
  EXPECT_EQ(result.candidates[0].reason, "");
  EXPECT_NEAR(result.candidates[0].verification.T_candidate_query.translation().x(), 0.3, 0.02);
  // The graph moves the second keyframe back onto the truth, relative to the first.
  EXPECT_NEAR((result.T_odom_lidar_corrected[0].inverse() * result.T_odom_lidar_corrected[1]).translation().x(), 0.3,
              0.02);
  EXPECT_GT(result.candidates[0].graph_weight, 0.9);
}

TEST(LoopClosure, ASymmetricPlaceThatRegistersWellIsRefusedByTheOdometry) {
  const auto scene = symmetricHall();
  LoopClosure closure{LoopClosureConfig{}, lidar::RegistrationConfig{}};
  EXPECT_FALSE(closure.addKeyframe(keyframe(scene, at(-5, 0), at(-5, 0), 0.0, 0.0)));
  EXPECT_FALSE(closure.addKeyframe(keyframe(scene, at(5, M_PI), at(5, M_PI), 30.0, 20.0)));
  const LoopClosureResult result = closure.solve();
  ASSERT_EQ(result.candidates.size(), 1u);
  const LoopCandidateRecord& c = result.candidates[0];
  EXPECT_TRUE(c.verification.accepted) << c.verification.reason;  // the ICP alone is fooled
  EXPECT_EQ(c.reason.rfind("off the odometry by", 0), 0u) << c.reason;
  EXPECT_TRUE(result.T_odom_lidar_corrected[1].isApprox(result.T_odom_lidar[1]));
}

// The same loop gated again on better keyframe poses (fused mode's): the
// LiDAR odometry drifted 2 m over the lap and refused it; on poses 5 cm off
// it passes and the graph takes it. The half-turned place stays refused.
TEST(LoopClosure, ALoopRefusedOnADriftedOdometryIsTakenOnBetterPoses) {
  const auto scene = symmetricHall();
  LoopClosure closure{LoopClosureConfig{}, lidar::RegistrationConfig{}};
  EXPECT_FALSE(closure.addKeyframe(keyframe(scene, at(-5, 0), at(-5, 0), 0.0, 0.0)));
  EXPECT_FALSE(closure.addKeyframe(keyframe(scene, at(-4.7, 0), at(-2.7, 0), 30.0, 20.0)));
  const LoopClosureResult live = closure.solve();
  ASSERT_EQ(live.candidates.size(), 1u);
  EXPECT_EQ(live.candidates[0].reason.rfind("off the odometry by", 0), 0u) << live.candidates[0].reason;

  const LoopClosureResult better = regateWithOdometry(live, {at(-5, 0), at(-4.65, 0)}, "fused", LoopClosureConfig{});
  EXPECT_EQ(better.odometry, "fused");
  ASSERT_EQ(better.accepted(), 1u);
  ASSERT_TRUE(better.solved);
  EXPECT_NEAR((better.T_odom_lidar_corrected[0].inverse() * better.T_odom_lidar_corrected[1]).translation().x(), 0.3,
              0.02);
  EXPECT_GT(better.candidates[0].graph_weight, 0.9);
  EXPECT_EQ(better.path_lengths, live.path_lengths);
}

TEST(LoopClosure, ASymmetricPlaceStaysRefusedOnExactPoses) {
  const auto scene = symmetricHall();
  LoopClosure closure{LoopClosureConfig{}, lidar::RegistrationConfig{}};
  closure.addKeyframe(keyframe(scene, at(-5, 0), at(-5, 0), 0.0, 0.0));
  closure.addKeyframe(keyframe(scene, at(5, M_PI), at(5, M_PI), 30.0, 20.0));
  const LoopClosureResult again =
      regateWithOdometry(closure.solve(), {at(-5, 0), at(5, M_PI)}, "fused", LoopClosureConfig{});
  ASSERT_EQ(again.candidates.size(), 1u);
  EXPECT_TRUE(again.candidates[0].verification.accepted);
  EXPECT_EQ(again.candidates[0].reason.rfind("off the odometry by", 0), 0u) << again.candidates[0].reason;
  EXPECT_EQ(again.accepted(), 0u);
}

}  // namespace
}  // namespace lvslam::loop
