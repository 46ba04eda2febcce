// Relocalisation pose guesses (the motion model's pose first, then the last
// pose, then the reference keyframe) and the motion model in time.
#include "lvslam/visual/tracking/motion_model.h"
#include "lvslam/visual/tracking/relocalization.h"

#include <cmath>

#include <gtest/gtest.h>

#include "lvslam/core/se3.h"

namespace lvslam::visual {
namespace {

Eigen::Isometry3d pose(double x, double yaw) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(x, 0.1, 0.2);
  return T;
}

TEST(Relocalization, GuessesAreTheMotionModelsPoseThenTheLastThenTheReferenceKeyframes) {
  VisualMap map;
  Keyframe k;
  k.T_camera_world = pose(5.0, 0.3);
  const int reference = map.addKeyframe(k);
  const Eigen::Isometry3d T_last = pose(1.0, 0.0);
  const Eigen::Isometry3d T_extrapolated = pose(1.3, 0.03);
  const std::vector<Eigen::Isometry3d> guesses = relocalizationGuesses(map, T_extrapolated, T_last, reference, 4);
  ASSERT_EQ(guesses.size(), 3u);  // no covisible neighbours in this map
  EXPECT_TRUE(guesses[0].isApprox(T_extrapolated, 1e-12));
  EXPECT_TRUE(guesses[1].isApprox(T_last, 1e-12));
  EXPECT_TRUE(guesses[2].isApprox(k.T_camera_world, 1e-12));
  EXPECT_EQ(relocalizationGuesses(map, T_extrapolated, T_last, reference + 7, 4).size(), 2u);  // unknown reference
}

// Regular frames: the velocity once per interval, bit for bit what the
// frame-counting model gave; dropped frames and jumps: as many intervals as
// passed; fractions of an interval: the scaled motion.
TEST(MotionModel, StepsFollowTheElapsedTime) {
  const Eigen::Isometry3d T_last = pose(1.0, 0.2);
  const Eigen::Isometry3d v = pose(0.1, 0.01);
  const ConstantVelocity model{v, 1.0 / 15.0};
  EXPECT_TRUE(predictPose(model, T_last, 1.0 / 15.0).matrix() == (v * T_last).matrix());
  EXPECT_TRUE(predictPose(model, T_last, 1.1 / 15.0).matrix() == (v * T_last).matrix());  // jitter
  EXPECT_TRUE(predictPose(model, T_last, 3.0 / 15.0).matrix() == (v * (v * (v * T_last))).matrix());
  // Half an interval: the motion whose square is one step.
  const Eigen::Isometry3d half = predictPose(model, T_last, 0.5 / 15.0) * T_last.inverse();
  EXPECT_TRUE((half * half).isApprox(v, 1e-12));
  // 2.5 intervals: exp(2.5 log v).
  const Eigen::Isometry3d two_and_half = predictPose(model, T_last, 2.5 / 15.0) * T_last.inverse();
  EXPECT_TRUE((half.inverse() * two_and_half).isApprox(v * v, 1e-12));
  // A long gap: the same motion, scaled instead of repeated.
  const Eigen::Isometry3d long_gap = predictPose(model, T_last, 100.0 / 15.0) * T_last.inverse();
  EXPECT_TRUE(long_gap.isApprox(expSE3(100.0 * logSE3(v)), 1e-9));
  // No time, or an unknown span: one step, as frame counting did.
  EXPECT_TRUE(predictPose(model, T_last, 0.0).isApprox(T_last, 1e-12));
  EXPECT_TRUE(predictPose(ConstantVelocity{v, 0.0}, T_last, 5.0).matrix() == (v * T_last).matrix());
  EXPECT_TRUE(predictPose(model, T_last, std::nan("")).matrix() == (v * T_last).matrix());
}

}  // namespace
}  // namespace lvslam::visual
