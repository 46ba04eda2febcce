#include "lvslam/eval/rpe.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "eval/eval_test_trajectories.h"

namespace lvslam::eval {
namespace {

using testing::evenlySpaced;
using testing::posesAlongX;


TEST(RpePairs, FollowEvoFilterPairsByPath) {
  // Steps 3,3,3,3,5,5,2,2,2,2,2,4,4,4 with delta 6: a mark each time the path
  // since the last mark reaches 6. Pose 0 is not a mark, so the first pair
  // starts at pose 2.
  const auto poses = posesAlongX({0, 3, 6, 9, 12, 17, 22, 24, 26, 28, 30, 32, 36, 40, 44});
  const std::vector<PoseIndexPair> expected{{2, 4}, {4, 6}, {6, 9}, {9, 12}, {12, 14}};
  EXPECT_EQ(consecutivePairsByPath(poses, 6.0), expected);
}

TEST(RpePairs, PathShorterThanTwoDeltasHasNoPairs) {
  EXPECT_TRUE(consecutivePairsByPath(posesAlongX({0, 3, 6, 9, 11}), 6.0).empty());
}

TEST(Rpe, StraightLineWithScaleErrorHasTheKnownPerPairError) {
  const auto gt = posesAlongX(evenlySpaced(31, 1.0));
  const auto est = posesAlongX(evenlySpaced(31, 0.9));  // 10 % short
  // On the ground truth: pairs (10,20), (20,30), each 10 m against 9 m.
  const RpeResult on_gt = computeRpe(gt, est, 10.0, RpePairsOn::kGroundTruth);
  ASSERT_EQ(on_gt.pairs, (std::vector<PoseIndexPair>{{10, 20}, {20, 30}}));
  EXPECT_NEAR(on_gt.translation.max, 1.0, 1e-9);
  EXPECT_NEAR(on_gt.translation.min, 1.0, 1e-9);
  EXPECT_NEAR(on_gt.rotation_deg.max, 0.0, 1e-9);
  // On the estimate (0.9 m steps): the 10 m marks fall at poses 12 and 24.
  const RpeResult on_est = computeRpe(gt, est, 10.0, RpePairsOn::kEstimate);
  ASSERT_EQ(on_est.pairs, (std::vector<PoseIndexPair>{{12, 24}}));
  EXPECT_NEAR(on_est.translation.mean, 1.2, 1e-9);
}

TEST(Rpe, YawDriftGivesTheKnownRotationAndTranslationErrors) {
  // est_k = gt_k * Rz(alpha k): E = (Rz(alpha (j-i)), Rz(-alpha i) d - d) for
  // the gt motion d, so |t(E)| = 2 |d| sin(alpha i / 2).
  const double alpha = 0.5 * std::numbers::pi / 180.0;
  const auto gt = posesAlongX(evenlySpaced(31, 1.0));
  auto est = gt;
  for (std::size_t k = 0; k < est.size(); ++k)
    est[k].linear() = Eigen::AngleAxisd(alpha * static_cast<double>(k), Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const RpeResult rpe = computeRpe(gt, est, 10.0, RpePairsOn::kGroundTruth);
  ASSERT_EQ(rpe.pairs.size(), 2u);
  EXPECT_NEAR(rpe.translation_errors[0], 20.0 * std::sin(10 * alpha / 2), 1e-9);
  EXPECT_NEAR(rpe.translation_errors[1], 20.0 * std::sin(20 * alpha / 2), 1e-9);
  EXPECT_NEAR(rpe.rotation_errors_deg[0], 5.0, 1e-9);
  EXPECT_NEAR(rpe.rotation_errors_deg[1], 5.0, 1e-9);
}

}  // namespace
}  // namespace lvslam::eval
