// The loop closure's thread gives what the deterministic run gives after
// the run: same candidates, same corrected keyframes; it re-solves the
// graph live after an accepted loop.
#include <gtest/gtest.h>

#include "loop/loop_scenes.h"
#include "lvslam/core/se3.h"
#include "lvslam/system/offline/loop_closure_worker.h"

namespace lvslam::system {
namespace {

std::vector<loop::LoopKeyframe> aLap() {
  const auto scene = testing::structuredRoom();
  std::vector<loop::LoopKeyframe> keyframes;
  // Out along x, and back 20 m of path later with 0.08 m of drift.
  for (int k = 0; k < 4; ++k) {
    const Eigen::Isometry3d T = makePose(Eigen::Quaterniond::Identity(), Eigen::Vector3d(-4.0 + k, 0.0, 1.0));
    keyframes.push_back({static_cast<double>(k), T, testing::keyframeFeatures(scene, T), static_cast<double>(k)});
  }
  const Eigen::Isometry3d back = makePose(Eigen::Quaterniond::Identity(), Eigen::Vector3d(-3.9, 0.0, 1.0));
  Eigen::Isometry3d drifted = back;
  drifted.translation().x() += 0.08;
  keyframes.push_back({30.0, drifted, testing::keyframeFeatures(scene, back), 23.0});
  return keyframes;
}

loop::LoopClosureResult run(bool threaded, std::vector<Eigen::Isometry3d>* live = nullptr, int* live_solves = nullptr) {
  LoopClosureWorker worker(loop::LoopClosureConfig{}, lidar::RegistrationConfig{}, threaded);
  for (loop::LoopKeyframe& keyframe : aLap()) worker.add(std::move(keyframe));
  loop::LoopClosureResult result = worker.finish();
  if (live) *live = worker.latestCorrectedPoses();
  if (live_solves) *live_solves = worker.liveSolves();
  return result;
}

TEST(LoopClosureWorker, TheThreadGivesTheDeterministicResult) {
  std::vector<Eigen::Isometry3d> live;
  int live_solves = 0;
  const loop::LoopClosureResult threaded = run(true, &live, &live_solves);
  const loop::LoopClosureResult deterministic = run(false);
  ASSERT_EQ(threaded.accepted(), 1u);
  ASSERT_EQ(threaded.candidates.size(), deterministic.candidates.size());
  for (std::size_t k = 0; k < threaded.T_odom_lidar_corrected.size(); ++k)
    EXPECT_TRUE(threaded.T_odom_lidar_corrected[k].matrix() == deterministic.T_odom_lidar_corrected[k].matrix()) << k;
  EXPECT_EQ(live_solves, 1);
  ASSERT_EQ(live.size(), 5u);
  // The loop pulls the drifted keyframe back toward x = -3.9.
  EXPECT_LT(std::abs(threaded.T_odom_lidar_corrected[4].translation().x() + 3.9), 0.03);
}

}  // namespace
}  // namespace lvslam::system
