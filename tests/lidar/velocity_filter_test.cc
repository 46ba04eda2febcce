// The LiDAR's constant-velocity model as a Kalman filter: exact values.
#include <gtest/gtest.h>

#include "lvslam/lidar/velocity_filter.h"

namespace lvslam::lidar {
namespace {

constexpr double kDt = 0.1;
const VelocityNoise kNoise{2.0, 1.5};  // m/s^2, rad/s^2

TEST(VelocityFilter, EachDirectionIsTheInformationWeightedMeanOfPredictionAndStep) {
  VelocityEstimate previous;
  previous.velocity << 1.0, 0.0, 0.0, 0.0, 0.0, 0.2;
  previous.covariance = Matrix6d::Identity() * 0.01;
  Vector6d measured;
  measured << 1.4, 0.1, -0.1, 0.05, 0.0, 0.1;
  Vector6d pose_sigma;  // metres and radians
  pose_sigma << 0.05, 0.002, 0.002, 0.001, 0.001, 0.001;
  const Matrix6d information = pose_sigma.cwiseInverse().cwiseAbs2().asDiagonal();
  const VelocityEstimate next = updateVelocity(previous, measured, information, kDt, kNoise);
  for (int i = 0; i < 6; ++i) {
    const double accel = i < 3 ? kNoise.accel : kNoise.angular_accel;
    const double predicted_variance = 0.01 + accel * kDt * accel * kDt;
    const double step_variance = 2.0 * pose_sigma(i) * pose_sigma(i) / (kDt * kDt);
    const double gain = predicted_variance / (predicted_variance + step_variance);
    EXPECT_NEAR(next.velocity(i), previous.velocity(i) + gain * (measured(i) - previous.velocity(i)), 1e-12) << i;
    EXPECT_NEAR(next.covariance(i, i), (1.0 - gain) * predicted_variance, 1e-12) << i;
  }
  // The poorly seen axis (5 cm) takes a tenth of the step's 0.4 m/s; the
  // well seen ones (2 mm) almost all of theirs.
  EXPECT_LT(next.velocity(0), 1.1);
  EXPECT_NEAR(next.velocity(1), 0.1, 0.01);
}

TEST(VelocityFilter, ADirectionTheScanDidNotSeeKeepsThePredictionAndGrowsUncertain) {
  VelocityEstimate previous;
  previous.velocity << 1.0, 0.3, 0.0, 0.0, 0.0, 0.1;
  previous.covariance = Matrix6d::Identity() * 0.04;
  Vector6d measured;
  measured << 5.0, 0.3, 0.0, 0.0, 0.0, 0.1;  // a slide along x
  Matrix6d information = Matrix6d::Identity() * 1e6;
  information(0, 0) = 0.0;  // x not seen
  const VelocityEstimate next = updateVelocity(previous, measured, information, kDt, kNoise);
  EXPECT_DOUBLE_EQ(next.velocity(0), 1.0);
  EXPECT_NEAR(next.covariance(0, 0), 0.04 + 0.2 * 0.2, 1e-12);
  EXPECT_NEAR(next.velocity(1), 0.3, 1e-12);
}

TEST(VelocityFilter, FromNothingKnownAPreciseStepIsTheVelocity) {
  Vector6d measured;
  measured << 0.8, -0.2, 0.01, 0.0, 0.02, -0.3;
  const VelocityEstimate next =
      updateVelocity(VelocityEstimate{}, measured, Matrix6d::Identity() * 1e6, kDt, kNoise);
  EXPECT_LT((next.velocity - measured).norm(), 1e-5);
}

TEST(VelocityFilter, NoTimeBetweenThePosesChangesNothing) {
  VelocityEstimate previous;
  previous.velocity << 1, 2, 3, 4, 5, 6;
  const VelocityEstimate next = updateVelocity(previous, Vector6d::Zero(), Matrix6d::Identity(), 0.0, kNoise);
  EXPECT_EQ(next.velocity, previous.velocity);
  EXPECT_EQ(next.covariance, previous.covariance);
}

}  // namespace
}  // namespace lvslam::lidar
