// Multi-metric ICP recovers a known transform between two scans of one scene.
#include <gtest/gtest.h>

#include "lidar/synthetic_lidar.h"
#include "lvslam/lidar/feature_extraction.h"
#include "lvslam/lidar/multi_metric_icp.h"
#include "lvslam/lidar/preprocess.h"

namespace lvslam::lidar {
namespace {

FeatureFrame staticFrame(const testing::SyntheticScene& scene, const Eigen::Isometry3d& T_world_lidar,
                         const LidarOdometryConfig& config, std::uint32_t seq) {
  testing::SyntheticSensor sensor;
  sensor.columns = 1024;
  const LidarScan scan = testing::castScan(scene, [&](double) { return T_world_lidar; }, 0.0, sensor);
  FeatureFrame frame;
  frame.seq = seq;
  frame.T_world_lidar = T_world_lidar;
  frame.points = extractFeatures(cropAndDownsample(scan, config.preprocess), config.ground, config.features);
  return frame;
}

TEST(MultiMetricIcp, RecoversAKnownTransformToAMillimetreScale) {
  const LidarOdometryConfig config;
  const auto scene = testing::structuredRoom();
  const Eigen::Isometry3d T_world_a = makePose(Eigen::Quaterniond::Identity(), Eigen::Vector3d(-2, 0.5, 1.0));
  LocalMap map(config.local_map);
  map.update(staticFrame(scene, T_world_a, config, 0));
  // The second scan from 0.4 m away, turned 4 deg in yaw and 0.5 deg in pitch and roll.
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(0.07, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(0.009, Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(-0.009, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  const Eigen::Isometry3d T_world_b = T_world_a * makePose(R, Eigen::Vector3d(0.35, -0.15, 0.05));
  const FeatureFrame b = staticFrame(scene, T_world_b, config, 1);
  // Searching neighbours every iteration, or only after the pose moved.
  for (const double reassociate_motion : {0.0, 0.02}) {
    RegistrationConfig registration = config.registration;
    registration.reassociate_motion = reassociate_motion;
    const IcpResult result = registerMultiMetric(b.points, map, T_world_a, 1.0, registration);
    const Eigen::Isometry3d error = T_world_b.inverse() * result.T_world_lidar;
    EXPECT_LT(error.translation().norm(), 0.01) << reassociate_motion;
    EXPECT_LT(rotationAngle(error) * 180.0 / M_PI, 0.1) << reassociate_motion;
    EXPECT_FALSE(result.degenerate);
    EXPECT_TRUE(result.converged) << reassociate_motion;
  }
}

}  // namespace
}  // namespace lvslam::lidar
