// Geometric verification accepts a true revisit with its relative pose and
// rejects a candidate from another place, whatever the descriptor said.
#include <cmath>

#include <gtest/gtest.h>

#include "loop/loop_scenes.h"
#include "lvslam/core/se3.h"
#include "lvslam/loop/loop_verification.h"
#include "lvslam/loop/scan_context.h"

namespace lvslam::loop {
namespace {

const Eigen::Isometry3d kCandidate = makePose(Eigen::Quaterniond::Identity(), Eigen::Vector3d(-2.0, 0.5, 1.0));

LoopVerification verify(const std::vector<lidar::FeaturePoint>& query, const std::vector<lidar::FeaturePoint>& candidate) {
  const LoopClosureConfig config;
  const double yaw = compareScanContexts(scanContextOf(query, config.scan_context),
                                         scanContextOf(candidate, config.scan_context))
                         .yaw;
  return verifyLoop(query, {{Eigen::Isometry3d::Identity(), &candidate}}, yaw, config, lidar::RegistrationConfig());
}

TEST(LoopVerification, AcceptsARevisitAndRecoversTheRelativePose) {
  const auto scene = testing::structuredRoom();
  // Back 0.7 m off and turned 50 deg: the descriptor gives the yaw, ICP the rest.
  const Eigen::Isometry3d T_candidate_query =
      makePose(Eigen::Matrix3d(Eigen::AngleAxisd(50.0 * M_PI / 180.0, Eigen::Vector3d::UnitZ())),
               Eigen::Vector3d(0.6, -0.35, 0.03));
  const auto candidate = testing::keyframeFeatures(scene, kCandidate);
  const auto query = testing::keyframeFeatures(scene, kCandidate * T_candidate_query);
  const LoopVerification v = verify(query, candidate);
  ASSERT_TRUE(v.accepted) << v.reason;
  const Eigen::Isometry3d error = T_candidate_query.inverse() * v.T_candidate_query;
  EXPECT_LT(error.translation().norm(), 0.02);
  EXPECT_LT(rotationAngle(error) * 180.0 / M_PI, 0.2);
  EXPECT_FALSE(v.degenerate);
  EXPECT_TRUE(v.information.allFinite());
  EXPECT_GT(v.information.determinant(), 0.0);
}

TEST(LoopVerification, RejectsACandidateFromAnotherPlace) {
  const auto candidate = testing::keyframeFeatures(testing::structuredRoom(), kCandidate);
  const auto query = testing::keyframeFeatures(testing::storeRoom(), kCandidate);
  const LoopVerification v = verify(query, candidate);
  EXPECT_FALSE(v.accepted);
  EXPECT_FALSE(v.reason.empty());
}

TEST(LoopVerification, RejectsAFloorWithoutWallsAsDegenerate) {
  const auto floor = testing::keyframeFeatures(testing::floorOnly(), kCandidate);
  const LoopVerification v = verify(floor, floor);
  EXPECT_FALSE(v.accepted);
  EXPECT_TRUE(v.degenerate) << v.reason;
  EXPECT_EQ(v.reason.rfind("degenerate", 0), 0u) << v.reason;
}

}  // namespace
}  // namespace lvslam::loop
