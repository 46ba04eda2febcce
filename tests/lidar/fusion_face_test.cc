// The face the fusion framework uses: direction updates on named linear points,
// the alpha rule on refined points in the local map, features at camera times.
#include <algorithm>

#include <gtest/gtest.h>

#include "lidar/synthetic_lidar.h"
#include "lvslam/core/error.h"
#include "lvslam/lidar/lidar_odometry.h"

namespace lvslam::lidar {
namespace {

LidarScan driveScan(double t) { return testing::castScan(testing::structuredRoom(), testing::drivePose, t, {}); }

std::vector<FeatureId> linearIds(const FeatureFrame& frame) {
  std::vector<FeatureId> ids;
  for (std::size_t i = 0; i < frame.points.size(); ++i)
    if (isLinear(frame.points[i].cls)) ids.push_back(frame.id(i));
  return ids;
}

TEST(FusionFace, SetLinearDirectionsChangesExactlyTheNamedPoints) {
  LidarOdometry odometry{LidarOdometryConfig{}};
  odometry.process(driveScan(0.0));
  odometry.prepare(driveScan(0.1));
  const FeatureFrame before = odometry.currentFrame();
  std::vector<FeatureId> named = linearIds(before);
  ASSERT_GE(named.size(), 6u);
  named.resize(named.size() / 2);
  // A non-linear point and an unknown id are skipped.
  const auto planar = std::find_if(before.points.begin(), before.points.end(),
                                   [](const FeaturePoint& fp) { return isPlanar(fp.cls); });
  std::vector<FeatureId> request = named;
  request.push_back(before.id(planar - before.points.begin()));
  request.push_back(makeFeatureId(999, 0));
  const Eigen::Vector3d d_world = Eigen::Vector3d(0.1, 0.0, 1.0).normalized();
  EXPECT_EQ(odometry.setLinearDirections(request, d_world), named.size());
  const FeatureFrame& after = odometry.currentFrame();
  const Eigen::Matrix3d R_world_lidar = before.T_world_lidar.linear();
  for (std::size_t i = 0; i < before.points.size(); ++i) {
    const bool is_named = std::count(named.begin(), named.end(), before.id(i)) > 0;
    EXPECT_EQ(after.points[i].refined, is_named) << i;
    if (is_named) {
      EXPECT_LT((R_world_lidar * after.points[i].direction.cast<double>() - d_world).norm(), 1e-6);
    } else {
      EXPECT_EQ(after.points[i].direction, before.points[i].direction) << i;
    }
    EXPECT_EQ(after.points[i].p, before.points[i].p);
  }
  EXPECT_THROW(odometry.setLinearDirections(named, Eigen::Vector3d::Zero()), Error);
  // Registration takes the refined points into the map as refined.
  EXPECT_EQ(odometry.registerScan().status, OdometryStatus::kTracking);
  EXPECT_GT(odometry.localMap().refinedCount(), 0u);
}

TEST(FusionFace, AlphaBoundsTheRateOfRefinedPointsInTheLocalMap) {
  for (const double alpha : {0.05, 0.2}) {
    LidarOdometryConfig config;
    config.local_map.refined_rate_alpha = alpha;
    LidarOdometry odometry{config};
    for (int i = 0; i < 6; ++i) {
      odometry.prepare(driveScan(0.1 * i));
      // Refine every linear point of the frame and of the recent frames.
      std::vector<FeatureId> ids = linearIds(odometry.currentFrame());
      for (const FeatureFrame& frame : odometry.recentFrames()) {
        const auto more = linearIds(frame);
        ids.insert(ids.end(), more.begin(), more.end());
      }
      odometry.setLinearDirections(ids, Eigen::Vector3d::UnitZ());
      odometry.registerScan();
      EXPECT_LE(odometry.localMap().refinedRate(), alpha) << "alpha " << alpha << " frame " << i;
      EXPECT_GT(odometry.localMap().refinedCount(), 0u);
    }
  }
}

TEST(FusionFace, FeaturesAtACameraTimeFollowTheMotionEstimate) {
  LidarOdometry odometry{LidarOdometryConfig{}};
  for (int i = 0; i < 4; ++i) odometry.process(driveScan(0.1 * i));
  odometry.prepare(driveScan(0.4));
  const double t_camera = 0.4 + 0.07;
  const auto moved = odometry.currentFeaturesAt(t_camera);
  const FeatureFrame& frame = odometry.currentFrame();
  ASSERT_EQ(moved.size(), frame.points.size());
  // Same world points either way: through the pose at t_camera or at the scan time.
  const Eigen::Isometry3d T_world_camera_time = odometry.poseAt(t_camera);
  for (std::size_t i = 0; i < moved.size(); i += 50) {
    const Eigen::Vector3d a = T_world_camera_time * moved[i].p.cast<double>();
    const Eigen::Vector3d b = frame.T_world_lidar * frame.points[i].p.cast<double>();
    EXPECT_LT((a - b).norm(), 1e-4);
  }
  // And the pose at the camera time is the true one (the sensor moved ~8 cm meanwhile).
  const Eigen::Isometry3d error = (testing::drivePose(0.0).inverse() * testing::drivePose(t_camera)).inverse() *
                                  odometry.poseAt(t_camera);
  EXPECT_LT(error.translation().norm(), 0.03);
}

}  // namespace
}  // namespace lvslam::lidar
