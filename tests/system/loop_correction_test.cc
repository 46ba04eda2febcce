// Loop corrections reach the refined trajectory and the map: each frame and
// each map point moves with its keyframe, in the odometry frame.
#include <gtest/gtest.h>

#include "lvslam/core/se3.h"
#include "lvslam/system/offline/loop_correction.h"

namespace lvslam::system {
namespace {

Eigen::Isometry3d pose(double yaw, double x, double y) {
  return makePose(Eigen::Matrix3d(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ())), Eigen::Vector3d(x, y, 0.0));
}

// Two keyframes at t = 1 and 3: the first stays, the second is moved 0.5 m along y and turned 0.1 rad.
loop::LoopClosureResult twoKeyframes() {
  loop::LoopClosureResult r;
  r.keyframe_times = {1.0, 3.0};
  r.T_odom_lidar = {pose(0.0, 0.0, 0.0), pose(0.3, 2.0, 0.0)};
  r.T_odom_lidar_corrected = {pose(0.0, 0.0, 0.0), pose(0.4, 2.0, 0.5)};
  r.solved = true;
  return r;
}

void expectPose(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  EXPECT_LT((a.translation() - b.translation()).norm(), 1e-12);
  EXPECT_LT(rotationAngle(a.inverse() * b), 1e-12);
}

TEST(LoopCorrection, EachFrameKeepsItsPoseRelativeToItsKeyframe) {
  const loop::LoopClosureResult result = twoKeyframes();
  const LoopCorrection correction(result);
  // Odometry frames at 0.5 (before any keyframe), 2 (first keyframe's) and 4 (second's).
  const Trajectory odometry = {{0.5, pose(0.0, -1.0, 0.0)}, {2.0, pose(0.1, 1.0, 0.0)}, {4.0, pose(0.5, 3.0, 1.0)}};
  const Trajectory corrected = correctTrajectory(odometry, odometry, correction);
  ASSERT_EQ(corrected.size(), 3u);
  expectPose(corrected[0].T_world_frame, odometry[0].T_world_frame);
  expectPose(corrected[1].T_world_frame, odometry[1].T_world_frame);
  // Relative to the second keyframe, the frame is where it was.
  expectPose(result.T_odom_lidar_corrected[1].inverse() * corrected[2].T_world_frame,
             result.T_odom_lidar[1].inverse() * odometry[2].T_world_frame);
}

TEST(LoopCorrection, ARefinedTrajectoryInAnotherWorldIsCorrectedInTheOdometryFrame) {
  const LoopCorrection correction(twoKeyframes());
  const Eigen::Isometry3d T_world_odom = pose(1.0, 5.0, -2.0);
  const Trajectory odometry = {{4.0, pose(0.5, 3.0, 1.0)}};
  const Trajectory refined = {{4.0, T_world_odom * odometry[0].T_world_frame}};
  const Trajectory corrected = correctTrajectory(refined, odometry, correction);
  ASSERT_EQ(corrected.size(), 1u);
  expectPose(corrected[0].T_world_frame, T_world_odom * correction.atTime(4.0) * odometry[0].T_world_frame);
}

TEST(LoopCorrection, MapPointsMoveWithTheKeyframeTheyWereAddedAfter) {
  const LoopCorrection correction(twoKeyframes());
  std::vector<PlyPoint> map(3);
  map[0].p = Eigen::Vector3f(1, 0, 0);
  map[1].p = Eigen::Vector3f(2, 1, 0);
  map[2].p = Eigen::Vector3f(3, 1, 0);
  const std::vector<PlyPoint> moved = correctMap(map, {0, 1}, correction);
  EXPECT_TRUE(moved[0].p.isApprox(map[0].p));
  for (std::size_t i = 1; i < 3; ++i)
    EXPECT_LT((moved[i].p - (correction.ofKeyframe(1).cast<float>() * map[i].p)).norm(), 1e-5f);
  EXPECT_GT((moved[2].p - map[2].p).norm(), 0.3f);
}

}  // namespace
}  // namespace lvslam::system
