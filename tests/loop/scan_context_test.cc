// Scan Context matches a scan to itself turned about z (and says by how
// much) and not to a different place.
#include <cmath>

#include <gtest/gtest.h>

#include "loop/loop_scenes.h"
#include "lvslam/core/se3.h"
#include "lvslam/loop/loop_config.h"
#include "lvslam/loop/scan_context.h"

namespace lvslam::loop {
namespace {

const Eigen::Isometry3d kHere = makePose(Eigen::Quaterniond::Identity(), Eigen::Vector3d(-2.0, 0.5, 1.0));

TEST(ScanContext, MatchesTheSameScanTurnedAboutZAndGivesTheTurn) {
  const ScanContextConfig config;
  const auto scene = testing::structuredRoom();
  const ScanContext candidate = scanContextOf(testing::keyframeFeatures(scene, kHere), config);
  for (const double yaw_deg : {0.0, 37.0, -100.0, 170.0}) {
    const double yaw = yaw_deg * M_PI / 180.0;
    const Eigen::Isometry3d T_world_query = kHere * Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ());
    const ScanContext query =
        scanContextOf(testing::keyframeFeatures(scene, T_world_query), config);
    const ScanContextMatch match = compareScanContexts(query, candidate);
    EXPECT_LT(match.distance, 0.1) << yaw_deg;
    // The yaw of the query in the candidate's frame, to one sector (6 deg).
    const double sector = 2.0 * M_PI / config.sectors;
    EXPECT_LE(std::abs(std::remainder(match.yaw - yaw, 2.0 * M_PI)), sector) << yaw_deg;
    // The ring key does not see the turn: closer to itself than to another place.
    const ScanContext elsewhere =
        scanContextOf(testing::keyframeFeatures(testing::storeRoom(), T_world_query), config);
    EXPECT_LT(ringKeyDistance(query, candidate), 0.5 * ringKeyDistance(elsewhere, candidate)) << yaw_deg;
  }
}

TEST(ScanContext, DoesNotMatchADifferentPlace) {
  const ScanContextConfig config;
  const ScanContext hall =
      scanContextOf(testing::keyframeFeatures(testing::structuredRoom(), kHere), config);
  const ScanContext store =
      scanContextOf(testing::keyframeFeatures(testing::storeRoom(), kHere), config);
  EXPECT_GT(compareScanContexts(store, hall).distance, LoopClosureConfig().max_descriptor_distance);
}

TEST(ScanContext, EmptyScansMatchNothing) {
  const ScanContextConfig config;
  const ScanContext empty = makeScanContext({}, config);
  EXPECT_EQ(compareScanContexts(empty, empty).distance, 1.0);
}

}  // namespace
}  // namespace lvslam::loop
