#include "lvslam/system/offline/refinement.h"

#include <gtest/gtest.h>

namespace lvslam::system {
namespace {

// The LiDAR lost from its second sweep on: after the run no frame has a
// pose both sweeps around it stood behind, so the replayed estimator never
// has a world. The refined trajectory must not come out empty.
TEST(Refinement, FusedFramesTheReplayCannotPoseKeepTheirOnlinePose) {
  PipelineRecords records;
  Trajectory online;
  for (int j = 0; j < 3; ++j) {
    VisualFrameRecord visual;
    visual.t = 0.1 * j;
    records.visual.push_back(visual);
    LidarFrameRecord lidar;
    lidar.t = visual.t;
    lidar.T_odom_lidar = Eigen::Isometry3d::Identity();
    lidar.pose_reliable = false;  // between a registered and a lost sweep
    records.lidar.push_back(lidar);
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation().x() = 0.5 * j;
    online.push_back({visual.t, T});
  }
  SystemConfig config;
  config.mode = RunMode::kFused;
  const Trajectory refined = refineTrajectory(records, config, Eigen::Isometry3d::Identity(), online);
  ASSERT_EQ(refined.size(), online.size());
  for (std::size_t j = 0; j < online.size(); ++j) {
    EXPECT_EQ(refined[j].t, online[j].t);
    EXPECT_TRUE(refined[j].T_world_frame.isApprox(online[j].T_world_frame));
  }
}

}  // namespace
}  // namespace lvslam::system
