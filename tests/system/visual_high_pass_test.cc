// The visual high-pass of the fused output (visual_high_pass.h) against
// values worked out by hand.
#include <cmath>

#include <gtest/gtest.h>

#include "lvslam/system/visual_high_pass.h"

namespace lvslam::system {
namespace {

const VisualHighPassConfig kConfig{.gain = 0.3, .gain_vertical = 0.3, .sigma_s = 0.2};  // window 0.6 s

TEST(VisualHighPass, AConstantOffsetPassesNothing) {
  VisualHighPass hp(kConfig);
  const Eigen::Vector3d offset(0.02, -0.01, 0.005);
  for (int j = 0; j < 30; ++j) EXPECT_LT(hp.add(j / 15.0, 0, offset).norm(), 1e-15) << j;
}

// A step of the difference at frame 10: at frame 10 the mean still holds the
// old frames, so the correction is gain * step * (1 - w_0 / sum of weights
// over the frames within 0.6 s), and it fades as the window fills with the
// new value; 0.6 s later the old frames have left and it is zero.
TEST(VisualHighPass, AStepPassesAShareThatFades) {
  VisualHighPass hp(kConfig);
  const double dt = 1.0 / 15.0;
  const Eigen::Vector3d step(0.0, 0.0, 0.01);
  double previous = 1.0;
  for (int j = 0; j < 30; ++j) {
    const Eigen::Vector3d d = j < 10 ? Eigen::Vector3d::Zero() : step;
    const Eigen::Vector3d c = hp.add(j * dt, 0, d);
    if (j < 10) {
      EXPECT_LT(c.norm(), 1e-15);
      continue;
    }
    double old_weights = 0.0, all_weights = 0.0;
    for (int k = 0; k <= j; ++k) {
      const double age = (j - k) * dt;
      if (age > 0.6 + 1e-12) continue;
      const double w = std::exp(-0.5 * (age / 0.2) * (age / 0.2));
      all_weights += w;
      if (k < 10) old_weights += w;
    }
    const double expected = 0.3 * 0.01 * old_weights / all_weights;
    EXPECT_NEAR(c.z(), expected, 1e-12) << j;
    EXPECT_NEAR(c.x(), 0.0, 1e-15);
    EXPECT_LE(c.z(), previous + 1e-15) << j;  // fades
    previous = c.z();
    if (j >= 20) {
      EXPECT_NEAR(c.z(), 0.0, 1e-15) << j;
    }
  }
}

// Vision leaving, or a new visual map, starts the mean anew: the first
// difference after it is its own mean and passes nothing.
TEST(VisualHighPass, AGapOrANewMapStartsAnew) {
  VisualHighPass hp(kConfig);
  const double dt = 1.0 / 15.0;
  for (int j = 0; j < 5; ++j) hp.add(j * dt, 0, Eigen::Vector3d::Zero());
  EXPECT_EQ(hp.add(5 * dt, 0, std::nullopt), Eigen::Vector3d::Zero());
  EXPECT_LT(hp.add(6 * dt, 0, Eigen::Vector3d(0.05, 0, 0)).norm(), 1e-15);
  EXPECT_GT(hp.add(7 * dt, 0, Eigen::Vector3d(0.06, 0, 0)).x(), 0.0);
  EXPECT_LT(hp.add(8 * dt, 1, Eigen::Vector3d(0.5, 0, 0)).norm(), 1e-15);  // map 1
}

TEST(VisualHighPass, GainZeroIsOff) {
  VisualHighPass hp({.gain = 0.0, .gain_vertical = 0.0, .sigma_s = 0.2});
  for (int j = 0; j < 10; ++j)
    EXPECT_EQ(hp.add(j / 15.0, 0, Eigen::Vector3d(j * 0.01, -j * 0.02, j * 0.03)), Eigen::Vector3d::Zero());
}

// The odometry frame's z takes its own share: a ramp of the same slope on
// each axis passes gain on x and y and gain_vertical on z of the same
// high-passed value.
TEST(VisualHighPass, TheVerticalTakesItsOwnShare) {
  VisualHighPass hp({.gain = 0.4, .gain_vertical = 0.8, .sigma_s = 0.2});
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int j = 0; j < 12; ++j) c = hp.add(j / 15.0, 0, Eigen::Vector3d::Constant(0.01 * j));
  ASSERT_GT(c.x(), 1e-4);
  EXPECT_NEAR(c.y(), c.x(), 1e-15);
  EXPECT_NEAR(c.z(), 2.0 * c.x(), 1e-15);
}

}  // namespace
}  // namespace lvslam::system
