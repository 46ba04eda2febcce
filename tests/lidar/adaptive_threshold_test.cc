// The adaptive correspondence threshold (kiss-icp, Vizzo et al. RA-L 2023,
// Sec. IV-C): 3 sigma of the model deviation at the largest range, where a
// correction (t, theta) deviates by |t| + 2 r_max sin(theta / 2), clamped.
#include "lvslam/lidar/adaptive_threshold.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lvslam::lidar {
namespace {

constexpr double kRange = 30.0;  // max_range of every case

Eigen::Isometry3d translation(double x, double y, double z) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}

Eigen::Isometry3d rotation(double angle, const Eigen::Vector3d& axis) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  return T;
}

TEST(AdaptiveThreshold, BeforeAnyCorrectionItIsTheInitialValueClamped) {
  EXPECT_DOUBLE_EQ(AdaptiveThreshold(0.7, 0.2, 2.0, kRange).threshold(), 0.7);
  EXPECT_DOUBLE_EQ(AdaptiveThreshold(5.0, 0.2, 2.0, kRange).threshold(), 2.0);
  EXPECT_DOUBLE_EQ(AdaptiveThreshold(0.1, 0.2, 2.0, kRange).threshold(), 0.2);
}

TEST(AdaptiveThreshold, ThreeSigmaOfTranslationCorrections) {
  AdaptiveThreshold th(0.7, 0.01, 10.0, kRange);
  th.update(translation(0.3, 0.0, 0.0));
  EXPECT_NEAR(th.threshold(), 3.0 * 0.3, 1e-12);
  th.update(translation(0.0, 0.24, 0.32));  // |t| = 0.4
  // sigma = sqrt((0.3^2 + 0.4^2) / 2) = sqrt(0.125)
  EXPECT_NEAR(th.threshold(), 3.0 * std::sqrt(0.125), 1e-12);
}

TEST(AdaptiveThreshold, ARotationCountsAsTheChordItSweepsAtMaxRange) {
  AdaptiveThreshold th(0.7, 0.01, 10.0, kRange);
  const double theta = 0.01;  // rad, about a tilted axis
  const double chord = 2.0 * kRange * std::sin(theta / 2.0);  // 0.2999987...
  Eigen::Isometry3d correction = rotation(theta, Eigen::Vector3d(1.0, -2.0, 0.5));
  correction.translation() = Eigen::Vector3d(0.0, 0.0, 0.1);
  th.update(correction);
  EXPECT_NEAR(th.threshold(), 3.0 * (chord + 0.1), 1e-9);
  th.update(rotation(theta, Eigen::Vector3d::UnitZ()));
  EXPECT_NEAR(th.threshold(), 3.0 * std::sqrt((std::pow(chord + 0.1, 2) + chord * chord) / 2.0), 1e-9);
}

TEST(AdaptiveThreshold, DeviationsOfAStandingRobotAreNotCounted) {
  AdaptiveThreshold th(0.7, 0.01, 10.0, kRange);
  // 4 cm, and a rotation whose chord at 30 m is 3 cm: below the 5 cm of a standing robot.
  th.update(translation(0.04, 0.0, 0.0));
  th.update(rotation(0.001, Eigen::Vector3d::UnitX()));
  EXPECT_DOUBLE_EQ(th.threshold(), 0.7);
  th.update(translation(0.2, 0.0, 0.0));
  th.update(translation(0.0, 0.01, 0.0));
  EXPECT_NEAR(th.threshold(), 3.0 * 0.2, 1e-12);
}

TEST(AdaptiveThreshold, IsClampedToItsBounds) {
  AdaptiveThreshold large(0.7, 0.2, 2.0, kRange);
  large.update(translation(1.0, 0.0, 0.0));  // 3 m
  EXPECT_DOUBLE_EQ(large.threshold(), 2.0);
  AdaptiveThreshold small(0.7, 0.2, 2.0, kRange);
  small.update(translation(0.06, 0.0, 0.0));  // 0.18 m
  EXPECT_DOUBLE_EQ(small.threshold(), 0.2);
}

}  // namespace
}  // namespace lvslam::lidar
