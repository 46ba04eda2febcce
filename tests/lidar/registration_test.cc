// Multi-metric ICP recovers a known transform between two scans of one scene.
#include <cmath>

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
  frame.points = extractFeatures(cropAndDownsample(scan, config.preprocess, config.features.neighbour_radius), config.ground, config.features);
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

// Three facade planes, x = 0.6 r_x, y = 0.6 r_y and z = 0.6 r_z, each
// sampled on its circle of radius r_axis about the sensor (every return of
// a plane at the same range, to float rounding); the scan's points are
// moved off their plane by +-1 cm and back onto their sphere.
FeatureFrame planesAtRanges(const Eigen::Vector3d& ranges, bool noisy) {
  FeatureFrame frame;
  for (int axis = 0; axis < 3; ++axis) {
    const double r = ranges(axis), a = 0.6 * r;
    const Eigen::Vector3d normal = Eigen::Vector3d::Unit(axis);
    const Eigen::Vector3d u = Eigen::Vector3d::Unit((axis + 1) % 3), v = Eigen::Vector3d::Unit((axis + 2) % 3);
    const double radius = std::sqrt(r * r - a * a);
    for (int k = 0; k < 60; ++k) {
      const double phi = 2.0 * M_PI * k / 60.0;
      const double offset = noisy ? ((k % 3) - 1) * 0.01 : 0.0;
      const Eigen::Vector3d on_plane = a * normal + radius * (std::cos(phi) * u + std::sin(phi) * v);
      FeaturePoint fp;
      fp.p = (r * (on_plane + offset * normal).normalized()).cast<float>();
      fp.direction = normal.cast<float>();
      fp.cls = FeatureClass::kFacade;
      frame.points.push_back(fp);
    }
  }
  return frame;
}

IcpResult registerPlanes(const Eigen::Vector3d& ranges, double beam_divergence) {
  const LidarOdometryConfig config;
  LocalMap map(config.local_map);
  map.update(planesAtRanges(ranges, false));
  RegistrationConfig registration = config.registration;
  registration.range_sigma = 0.02;
  registration.beam_divergence = beam_divergence;
  return registerMultiMetric(planesAtRanges(ranges, true).points, map, Eigen::Isometry3d::Identity(), 0.5,
                             registration);
}

// Each correspondence is weighed by its return's noise, range_sigma^2 /
// (range_sigma^2 + (r divergence / 4)^2): returns all equally far give the
// same registration and information as without (the residuals set the
// scale), while a far plane's say against a near one's drops by its weight.
TEST(MultiMetricIcp, EachCorrespondenceIsWeighedByItsReturnsNoise) {
  const auto weight = [](double r) {
    const double spread = r * 0.003 / 4.0;
    return 0.02 * 0.02 / (0.02 * 0.02 + spread * spread);  // 0.986 at 2 m, 0.64 at 20 m
  };
  const IcpResult same_sharp = registerPlanes(Eigen::Vector3d(20, 20, 20), 0.0);
  const IcpResult same_wide = registerPlanes(Eigen::Vector3d(20, 20, 20), 0.003);
  ASSERT_GT(same_sharp.correspondences, 150u);
  EXPECT_TRUE(same_sharp.T_world_lidar.isApprox(same_wide.T_world_lidar, 1e-6));
  EXPECT_LT((same_wide.information - same_sharp.information).norm(), 1e-5 * same_sharp.information.norm());

  const IcpResult mixed_sharp = registerPlanes(Eigen::Vector3d(2, 20, 2), 0.0);
  const IcpResult mixed_wide = registerPlanes(Eigen::Vector3d(2, 20, 2), 0.003);
  const double ratio_sharp = mixed_sharp.information(1, 1) / mixed_sharp.information(0, 0);
  const double ratio_wide = mixed_wide.information(1, 1) / mixed_wide.information(0, 0);
  EXPECT_NEAR(ratio_wide / ratio_sharp, weight(20.0) / weight(2.0), 1e-3);
}

}  // namespace
}  // namespace lvslam::lidar
