// The step gate: a subsystem's steps against its own constant velocity.
#include "lvslam/system/online/step_gate.h"

#include <random>

#include <gtest/gtest.h>

namespace lvslam::system {
namespace {

constexpr double kDt = 1.0 / 15.0;

Eigen::Isometry3d at(double x, double y = 0.0) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(x, y, 0.0);
  return T;
}

Matrix6d isotropicInformation(double sigma_m, double sigma_rad) {
  Vector6d d;
  d << Eigen::Vector3d::Constant(1.0 / (sigma_m * sigma_m)), Eigen::Vector3d::Constant(1.0 / (sigma_rad * sigma_rad));
  return d.asDiagonal();
}

// A subsystem that states 0.1 mm but jitters by 1 cm (Gaussian) sideways,
// beyond what 2 m/s^2 explains at 15 Hz (about 9 mm): the covariance
// matching learns a noise orders of magnitude above the stated one, and
// after it has, the ordinary jitter is rarely taken for a jump (at 99.9 %
// about one step in a thousand would be; the jitter's own extrapolation is
// not Gaussian, so allow a few).
TEST(StepGate, LearnsTheNoiseItsStepsShow) {
  StepGate gate(FactorSource::kLidar, StepGateConfig{});
  const Matrix6d stated = isotropicInformation(1e-4, 1e-4);
  std::mt19937 random(7);
  std::normal_distribution<double> jitter(0.0, 0.01);
  int gated_late = 0;
  for (int j = 0; j < 600; ++j) {
    const auto event = gate.check(kDt * j, at(0.05 * j, jitter(random)), stated);
    if (j >= 300 && event) ++gated_late;
  }
  EXPECT_GT(gate.noiseScale(), 1e3);
  EXPECT_LE(gated_late, 6);  // of 300
  // Without the matching (the stated noise kept), most steps would be jumps.
}

TEST(StepGate, AStatedNoiseThatHoldsIsKept) {
  StepGate gate(FactorSource::kVisual, StepGateConfig{});
  for (int j = 0; j < 100; ++j) EXPECT_FALSE(gate.check(kDt * j, at(0.05 * j), isotropicInformation(0.002, 0.001))) << j;
  EXPECT_DOUBLE_EQ(gate.noiseScale(), 1.0);
}

TEST(StepGate, AJumpIsGatedUnlessTheSubsystemIsAloneOrItLasts) {
  StepGateConfig config;
  config.accept_after = 2;
  const Matrix6d stated = isotropicInformation(0.002, 0.001);
  StepGate gate(FactorSource::kLidar, config), alone(FactorSource::kLidar, config);
  for (int j = 0; j < 10; ++j) {
    gate.check(kDt * j, at(0.05 * j), stated);
    alone.check(kDt * j, at(0.05 * j), stated);
  }
  // 1 m off, and staying off: gated twice, then a new start.
  const auto event = gate.check(kDt * 10, at(0.5, 1.0), stated);
  ASSERT_TRUE(event);
  EXPECT_EQ(event->source, FactorSource::kLidar);
  EXPECT_GT(event->chi_square, event->threshold);
  EXPECT_NE(event->reason.find("1.000 m"), std::string::npos) << event->reason;
  EXPECT_TRUE(gate.check(kDt * 11, at(0.55, 1.0), stated));
  EXPECT_FALSE(gate.restarted());
  EXPECT_FALSE(gate.check(kDt * 12, at(0.60, 1.0), stated));
  EXPECT_TRUE(gate.restarted());
  EXPECT_FALSE(gate.check(kDt * 13, at(0.65, 1.0), stated));  // on from the new start
  // Alone, nothing better would take its place: never gated.
  EXPECT_FALSE(alone.check(kDt * 10, at(0.5, 1.0), stated, true));
}

}  // namespace
}  // namespace lvslam::system
