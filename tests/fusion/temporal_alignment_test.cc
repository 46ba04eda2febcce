#include "lvslam/fusion/temporal_alignment.h"

#include <gtest/gtest.h>

#include "lvslam/core/se3.h"

namespace lvslam::fusion {
namespace {

// A LiDAR moving at constant twist: T_world_lidar(t) = T0 * exp(t * xi).
Eigen::Isometry3d truePose(double t) {
  Vector6d xi;
  xi << 1.2, 0.1, 0.0, 0.02, -0.01, 0.5;  // m/s and rad/s in the LiDAR frame
  return makePose(expSO3(Eigen::Vector3d(0.0, 0.0, 0.3)), Eigen::Vector3d(4.0, -2.0, 1.0)) * expSE3(t * xi);
}

TEST(TemporalAlignment, UndoesAKnownMotion) {
  // Points measured along a true constant-twist motion come out where the
  // camera at t_camera sees them, to within the slerp+lerp approximation of
  // a screw motion over 0.1 s (sub-millimetre).
  const double t0 = 100.0, t_camera = 100.0667;
  const Eigen::Isometry3d T_camera_lidar =
      makePose(expSO3(Eigen::Vector3d(-1.2, 1.2, -1.2)), Eigen::Vector3d(0.0, -0.25, -0.3));
  const ConstantVelocityMotion motion(t0, truePose(0.0), t0 + 0.1, truePose(0.1));
  const CameraTimeAligner align(motion, t_camera, T_camera_lidar);
  const Eigen::Vector3d p_world(7.0, 3.0, 0.5);
  const Eigen::Vector3d expected = T_camera_lidar * (truePose(t_camera - t0).inverse() * p_world);
  for (double t_point : {100.0, 100.03, 100.0667, 100.099}) {
    const Eigen::Vector3d p_lidar = truePose(t_point - t0).inverse() * p_world;  // the raw measurement
    EXPECT_LT((align(p_lidar, t_point) - expected).norm(), 1e-3) << t_point;
    // Without alignment the point would be off by the motion in between.
    if (t_point < 100.05) {
      EXPECT_GT((T_camera_lidar * p_lidar - expected).norm(), 0.02);
    }
  }
}

TEST(TemporalAlignment, InterpolatedMotionIsCloseToTheTrueScrewMotion) {
  // Over 0.1 s at robot speeds, slerp+lerp differs from the true constant
  // twist by far less than LiDAR noise.
  const ConstantVelocityMotion motion(0.0, truePose(0.0), 0.1, truePose(0.1));
  for (double t : {0.01, 0.05, 0.09}) {
    const Eigen::Isometry3d d = motion.poseAt(t).inverse() * truePose(t);
    EXPECT_LT(d.translation().norm(), 1e-3);
    EXPECT_LT(rotationAngle(d), 1e-6);
  }
}

TEST(TemporalAlignment, StationarySensorLeavesPointsAlone) {
  const Eigen::Isometry3d T = truePose(0.0);
  const ConstantVelocityMotion motion(0.0, T, 0.1, T);
  const CameraTimeAligner align(motion, 0.05, Eigen::Isometry3d::Identity());
  const Eigen::Vector3d p(1.0, 2.0, 3.0);
  EXPECT_LT((align(p, 0.0) - p).norm(), 1e-12);
  EXPECT_LT((align.rotate(Eigen::Vector3d::UnitX(), 0.0) - Eigen::Vector3d::UnitX()).norm(), 1e-12);
}

}  // namespace
}  // namespace lvslam::fusion
