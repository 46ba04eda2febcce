#include "lvslam/system/output_trajectory.h"

#include <gtest/gtest.h>

#include "lvslam/core/se3.h"

namespace lvslam::system {
namespace {

Eigen::Isometry3d trueCamera(double t) {
  Vector6d xi;
  xi << 0.0, 0.0, 1.0, 0.0, 0.3, 0.0;  // camera z forward at 1 m/s, turning about its y axis
  return makePose(expSO3(Eigen::Vector3d(0.1, 0.2, 0.3)), Eigen::Vector3d(1, 2, 3)) * expSE3(t * xi);
}

const Eigen::Isometry3d kTLidarCamera = makePose(expSO3(Eigen::Vector3d(1.2, -1.2, 1.2)), Eigen::Vector3d(0.3, 0, -0.2));

FrameEstimates exactEstimates(double t, int map_id, const Eigen::Isometry3d& T_map_world,
                              const Eigen::Isometry3d& T_odom_world) {
  FrameEstimates f;
  f.t = t;
  f.T_map_camera = T_map_world * trueCamera(t);
  f.visual_map_id = map_id;
  f.T_odom_lidar = T_odom_world * trueCamera(t) * kTLidarCamera.inverse();
  return f;
}

TEST(OutputTrajectory, ExactEstimatesGiveTheTruthUpToOneRigidTransformAcrossSwitches) {
  OutputTrajectory out(kTLidarCamera);
  const Eigen::Isometry3d map_a = expSE3((Vector6d() << 1, 2, 3, 0.1, 0.2, 0.3).finished());
  const Eigen::Isometry3d map_b = expSE3((Vector6d() << -4, 0, 1, 0.5, -0.2, 0.0).finished());  // after re-init
  const Eigen::Isometry3d odom = expSE3((Vector6d() << 7, 7, 7, 0.0, 0.0, 1.0).finished());
  for (int i = 0; i < 60; ++i) {
    const double t = 0.1 * i;
    const OutputSource src = (i >= 20 && i < 40) ? OutputSource::kLidar : OutputSource::kVisual;
    out.add(exactEstimates(t, i < 40 ? 0 : 1, i < 40 ? map_a : map_b, odom), src);
  }
  const Trajectory& traj = out.trajectory();
  ASSERT_EQ(traj.size(), 60u);
  const Eigen::Isometry3d align = traj[0].T_world_frame * trueCamera(0.0).inverse();
  for (const auto& p : traj) {
    const Eigen::Isometry3d err = (align * trueCamera(p.t)).inverse() * p.T_world_frame;
    EXPECT_LT(err.translation().norm(), 1e-9) << p.t;
    EXPECT_LT(rotationAngle(err), 1e-9) << p.t;
  }
}

TEST(OutputTrajectory, NoJumpWhenTheVisualMapIsOffAtTheSwitchBack) {
  // The LiDAR drifts while vision is out; the new visual map starts where
  // the output is, so the step at the switch is one frame's motion.
  OutputTrajectory out(kTLidarCamera);
  const Eigen::Isometry3d odom = Eigen::Isometry3d::Identity();
  for (int i = 0; i < 30; ++i) {
    const double t = 0.1 * i;
    FrameEstimates f = exactEstimates(t, i < 15 ? 0 : 1, Eigen::Isometry3d::Identity(), odom);
    // 2 cm of LiDAR drift per frame in the odometry.
    f.T_odom_lidar->translation() += Eigen::Vector3d(0.02 * i, 0.0, 0.0);
    if (i >= 15) f.T_map_camera = makePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(50, 0, 0)) * *f.T_map_camera;
    out.add(f, (i >= 10 && i < 15) ? OutputSource::kLidar : OutputSource::kVisual);
  }
  const Trajectory& traj = out.trajectory();
  for (std::size_t i = 1; i < traj.size(); ++i) {
    const double step = (traj[i].T_world_frame.translation() - traj[i - 1].T_world_frame.translation()).norm();
    EXPECT_LT(step, 0.2) << "jump at frame " << i;  // true motion is 0.1 m per frame
  }
}

// A visual glitch sends the output to the LiDAR for five frames while the
// LiDAR drifts 1 cm per frame; back in the same visual map the output first
// continues from where it is (no jump), then rejoins the map's own placement
// by at most the rejoin step per frame, and ends on it.
TEST(OutputTrajectory, BackInTheSameMapTheOutputRejoinsItsFirstAnchorByBoundedSteps) {
  const RejoinStep rejoin{0.002, 0.05};
  OutputTrajectory out(kTLidarCamera, rejoin);
  OutputTrajectory stays(kTLidarCamera);  // no rejoin: the offset stays for good
  for (int i = 0; i < 60; ++i) {
    FrameEstimates f = exactEstimates(0.1 * i, 0, Eigen::Isometry3d::Identity(), Eigen::Isometry3d::Identity());
    f.T_odom_lidar->translation() += Eigen::Vector3d(0.01 * i, 0.0, 0.0);
    const OutputSource src = (i >= 10 && i < 15) ? OutputSource::kLidar : OutputSource::kVisual;
    out.add(f, src);
    stays.add(f, src);
  }
  const Trajectory& traj = out.trajectory();
  const auto offset = [](const StampedPose& p) {
    return (p.T_world_frame.translation() - trueCamera(p.t).translation()).norm();
  };
  EXPECT_GT(offset(traj[15]), 0.04);  // five frames of 1 cm LiDAR drift
  EXPECT_NEAR(offset(stays.trajectory()[59]), offset(traj[15]), 1e-9);
  for (std::size_t i = 16; i < traj.size(); ++i) {
    const Eigen::Isometry3d step = traj[i - 1].T_world_frame.inverse() * traj[i].T_world_frame;
    const Eigen::Isometry3d true_step = trueCamera(traj[i - 1].t).inverse() * trueCamera(traj[i].t);
    const Eigen::Isometry3d extra = true_step.inverse() * step;
    EXPECT_LT(extra.translation().norm(), rejoin.max_m + 1e-9) << i;
    EXPECT_LT(rotationAngle(extra) * 180.0 / M_PI, rejoin.max_deg + 1e-9) << i;
  }
  EXPECT_LT(offset(traj[59]), 1e-9);
  const auto placements = out.mapPlacements();
  ASSERT_EQ(placements.count(0), 1u);
  EXPECT_TRUE(placements.at(0).isApprox(Eigen::Isometry3d::Identity(), 1e-12));
}

TEST(OutputTrajectory, LidarOnlyFollowsTheOdometryInTheCameraFrame) {
  OutputTrajectory out(kTLidarCamera);
  for (int i = 0; i < 10; ++i) {
    FrameEstimates f = exactEstimates(0.1 * i, 0, Eigen::Isometry3d::Identity(), Eigen::Isometry3d::Identity());
    f.T_map_camera.reset();
    out.add(f, OutputSource::kLidar);
  }
  for (const auto& p : out.trajectory()) {
    const Eigen::Isometry3d err = trueCamera(p.t).inverse() * p.T_world_frame;
    EXPECT_LT(err.translation().norm(), 1e-9);
  }
}

}  // namespace
}  // namespace lvslam::system
