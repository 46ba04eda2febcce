// Multi-metric ICP recovers a known transform between two scans of one scene.
#include <cmath>
#include <random>

#include <Eigen/Eigenvalues>
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

FeaturePoint featureAt(const Eigen::Vector3d& p, const Eigen::Vector3d& direction, FeatureClass cls) {
  FeaturePoint fp;
  fp.p = p.cast<float>();
  fp.direction = direction.normalized().cast<float>();
  fp.cls = cls;
  return fp;
}

// A corridor along x without ends: walls y = +-1.2, floor z = -1.2 and ceiling
// z = 1.6 about the sensor, with PCA normals tilted by up to +-5 deg toward
// the axis (what range noise and flush door frames do to them), and returns
// within +-5 mm of the surfaces.
FeatureFrame corridorFeatures(std::uint32_t seed, double max_tilt = 0.087) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> along(-12.0, 12.0), across(-1.0, 1.0), tilt(-max_tilt, max_tilt),
      noise(-0.005, 0.005);
  FeatureFrame frame;
  for (int i = 0; i < 600; ++i) {
    const int surface = i % 4;
    const double sign = surface % 2 == 0 ? 1.0 : -1.0;
    const Eigen::Vector3d normal = surface < 2 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ();
    const double offset = surface < 2 ? 1.2 : (sign > 0 ? 1.6 : 1.2);
    const Eigen::Vector3d in_plane = surface < 2 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d p = along(rng) * Eigen::Vector3d::UnitX() + across(rng) * in_plane +
                              (sign * offset + noise(rng)) * normal;
    frame.points.push_back(featureAt(p, normal + tilt(rng) * Eigen::Vector3d::UnitX(),
                                     surface < 2 ? FeatureClass::kFacade : FeatureClass::kGround));
  }
  return frame;
}

// Only rows aligned with a direction count toward seeing it (X-ICP): the
// walls' tilted normals add up to an eigenvalue along the axis that, counted
// whole (localizability_angle_deg 90), takes noise for information. Counted
// as aligned rows, the axis is not seen: it keeps the guess and carries no
// information, while the lateral offset is recovered.
TEST(MultiMetricIcp, ACorridorsAxisIsNotLocalizableAndKeepsTheGuess) {
  const LidarOdometryConfig config;
  LocalMap map(config.local_map);
  map.update(corridorFeatures(1));
  FeatureFrame moved = corridorFeatures(2);  // seen from 5 cm further along +y
  for (FeaturePoint& fp : moved.points) fp.p.y() -= 0.05f;

  const IcpResult result = registerMultiMetric(moved.points, map, Eigen::Isometry3d::Identity(), 0.5, config.registration);
  EXPECT_TRUE(result.degenerate);
  // The blind direction is x mixed with a little rotation (the tilts): x
  // moves well under a millimetre and keeps a sliver of information; counted
  // whole, x claims ten times as much.
  EXPECT_LT(std::abs(result.T_world_lidar.translation().x()), 1e-3);
  EXPECT_NEAR(result.T_world_lidar.translation().y(), 0.05, 0.005);
  EXPECT_LT(result.information(0, 0), 5e-4 * result.information(1, 1));

  RegistrationConfig every_row = config.registration;
  every_row.localizability_angle_deg = 90.0;
  const IcpResult whole = registerMultiMetric(moved.points, map, Eigen::Isometry3d::Identity(), 0.5, every_row);
  EXPECT_FALSE(whole.degenerate);
  EXPECT_GT(whole.information(0, 0), 2e-3 * whole.information(1, 1));
}

// The information reported along a seen direction is that of the rows
// aligned with it: a post fixes the corridor's axis, and the walls' tilted
// normals, which would add as much again counted whole, add nothing.
TEST(MultiMetricIcp, ASeenDirectionsInformationIsThatOfTheRowsAlignedWithIt) {
  const LidarOdometryConfig config;
  const Eigen::Isometry3d T_true = makePose(Eigen::Quaterniond::Identity(), Eigen::Vector3d(0.03, 0.02, 0.0));
  const auto axisInformation = [&](double max_tilt, double angle_deg) {
    FeatureFrame frame = corridorFeatures(1, max_tilt);
    for (int k = 0; k < 3; ++k)  // a post by the wall
      frame.points.push_back(featureAt(Eigen::Vector3d(4.0, 1.0, -0.8 + 0.8 * k), Eigen::Vector3d::UnitZ(),
                                       FeatureClass::kPillar));
    LocalMap map(config.local_map);
    map.update(frame);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> noise(-0.005, 0.005);
    std::vector<FeaturePoint> source = frame.points;
    for (FeaturePoint& fp : source)
      fp.p = (T_true.inverse() * fp.p.cast<double>() + Eigen::Vector3d(noise(rng), noise(rng), noise(rng)))
                 .cast<float>();
    RegistrationConfig registration = config.registration;
    registration.localizability_angle_deg = angle_deg;
    const IcpResult result = registerMultiMetric(source, map, Eigen::Isometry3d::Identity(), 0.5, registration);
    EXPECT_NEAR(result.T_world_lidar.translation().x(), 0.03, 0.01) << max_tilt << " " << angle_deg;
    return result.information(0, 0);
  };
  const double untilted = axisInformation(0.0, 75.0);
  const double tilted = axisInformation(0.087, 75.0);
  const double tilted_whole = axisInformation(0.087, 90.0);
  ASSERT_GT(untilted, 0.0);
  EXPECT_NEAR(tilted / untilted, 1.0, 0.15);
  EXPECT_GT(tilted_whole, 1.5 * tilted);
}

// Whether a direction is seen does not depend on what else is in view: three
// posts fix x, y and yaw to within the robust kernel however much ground
// surrounds them (an open yard), although their information is less than a
// thousandth of the ground's (the ratio test it replaced held them).
TEST(MultiMetricIcp, AFewPostsInOpenGroundAreSeenWhateverTheGround) {
  const LidarOdometryConfig config;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ground(-30.0, 30.0);
  FeatureFrame frame;
  for (int i = 0; i < 20000; ++i)
    frame.points.push_back(featureAt(Eigen::Vector3d(ground(rng), ground(rng), -1.5), Eigen::Vector3d::UnitZ(),
                                     FeatureClass::kGround));
  for (const Eigen::Vector2d& post : {Eigen::Vector2d(6, 2), Eigen::Vector2d(-3, 7), Eigen::Vector2d(-5, -6)})
    for (int k = 0; k < 3; ++k)
      frame.points.push_back(featureAt(Eigen::Vector3d(post.x(), post.y(), -1.0 + 0.8 * k), Eigen::Vector3d::UnitZ(),
                                       FeatureClass::kPillar));
  LocalMap map(config.local_map);
  map.update(frame);
  const Eigen::Isometry3d T_true = makePose(Eigen::Quaterniond(Eigen::AngleAxisd(0.01, Eigen::Vector3d::UnitZ())),
                                            Eigen::Vector3d(0.06, -0.04, 0.0));
  std::vector<FeaturePoint> source = frame.points;
  for (FeaturePoint& fp : source) {
    fp.p = (T_true.inverse() * fp.p.cast<double>()).cast<float>();
    fp.direction = (T_true.linear().transpose() * fp.direction.cast<double>()).cast<float>();
  }
  const IcpResult result = registerMultiMetric(source, map, Eigen::Isometry3d::Identity(), 0.5, config.registration);
  EXPECT_FALSE(result.degenerate);
  const Eigen::Isometry3d error = T_true.inverse() * result.T_world_lidar;
  EXPECT_LT(error.translation().norm(), 1e-3);
  EXPECT_LT(rotationAngle(error), 1e-4);
  const Eigen::SelfAdjointEigenSolver<Matrix6d> information(result.information);
  EXPECT_LT(information.eigenvalues()(0), 1e-3 * information.eigenvalues()(5));
}

// Three facade planes, x = 0.6 r_x, y = 0.6 r_y and z = 0.6 r_z, each
// sampled on its circle of radius r_axis about the sensor (every return of
// a plane at the same range, to float rounding) by 45, 60 and 75 returns
// (so that no two principal directions share an eigenvalue: each is
// defined, not one of a plane's worth); the scan's points are moved off
// their plane by +-1 cm and back onto their sphere.
FeatureFrame planesAtRanges(const Eigen::Vector3d& ranges, bool noisy) {
  FeatureFrame frame;
  for (int axis = 0; axis < 3; ++axis) {
    const double r = ranges(axis), a = 0.6 * r;
    const Eigen::Vector3d normal = Eigen::Vector3d::Unit(axis);
    const Eigen::Vector3d u = Eigen::Vector3d::Unit((axis + 1) % 3), v = Eigen::Vector3d::Unit((axis + 2) % 3);
    const double radius = std::sqrt(r * r - a * a);
    const int returns = 45 + 15 * axis;
    for (int k = 0; k < returns; ++k) {
      const double phi = 2.0 * M_PI * k / returns;
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
