#include "lvslam/system/offline/refinement.h"

#include <memory>

#include <gtest/gtest.h>

#include "lvslam/system/online/online_output.h"

namespace lvslam::system {
namespace {

// The online output over the frames, as the pipeline runs it, and the
// records the refinement reads after the run (the estimator's graph among them).
PipelineRecords recordsOf(const std::vector<VisualFrameRecord>& visual, const std::vector<LidarFrameRecord>& lidar,
                          const SystemConfig& config) {
  PipelineRecords records;
  const std::unique_ptr<OnlineOutput> output = makeOnlineOutput(config, Eigen::Isometry3d::Identity());
  for (std::size_t j = 0; j < visual.size(); ++j) {
    records.online.push_back(output->add(&visual[j], &lidar[j]));
    records.visual.push_back(visual[j]);
    records.lidar.push_back(lidar[j]);
  }
  records.estimator_graph = output->takeGraph();
  return records;
}

// The LiDAR lost from its second sweep on: no frame has a pose both sweeps
// around it stood behind, so the estimator never has a world and its graph
// is empty. The refined trajectory must not come out empty.
TEST(Refinement, FusedFramesTheGraphDoesNotHoldKeepTheirOnlinePose) {
  std::vector<VisualFrameRecord> visual_frames;
  std::vector<LidarFrameRecord> lidar_frames;
  Trajectory online;
  for (int j = 0; j < 3; ++j) {
    VisualFrameRecord visual;
    visual.t = 0.1 * j;
    visual_frames.push_back(visual);
    LidarFrameRecord lidar;
    lidar.t = visual.t;
    lidar.T_odom_lidar = Eigen::Isometry3d::Identity();
    lidar.pose_reliable = false;  // between a registered and a lost sweep
    lidar_frames.push_back(lidar);
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation().x() = 0.5 * j;
    online.push_back({visual.t, T});
  }
  SystemConfig config;
  config.mode = RunMode::kFused;
  const PipelineRecords records = recordsOf(visual_frames, lidar_frames, config);
  const Trajectory refined = refineTrajectory(records, config, Eigen::Isometry3d::Identity(), online).trajectory;
  ASSERT_EQ(refined.size(), online.size());
  for (std::size_t j = 0; j < online.size(); ++j) {
    EXPECT_EQ(refined[j].t, online[j].t);
    EXPECT_TRUE(refined[j].T_world_frame.isApprox(online[j].T_world_frame));
  }
}


// The fused refinement smooths the estimator's graph of vision as tracked:
// a visual map bent after its frames were tracked (its final keyframes
// place the frames 2 cm further sideways per frame, 0.58 m at the end)
// moves no refined pose.
TEST(Refinement, FusedRefinementTakesVisionAsTracked) {
  std::vector<VisualFrameRecord> visual_frames;
  std::vector<LidarFrameRecord> lidar_frames;
  Trajectory online;
  Vector6d information;
  information << Eigen::Vector3d::Constant(1e4), Eigen::Vector3d::Constant(1e6);
  for (int j = 0; j < 30; ++j) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation().x() = 0.05 * j;
    VisualFrameRecord visual;
    visual.t = j / 15.0;
    visual.result.state = visual::TrackingState::kTracking;
    visual.result.pose_valid = true;
    visual.result.metric = true;
    visual.result.T_world_camera = T;
    visual.result.fusion.pose_information = Matrix6d(information.asDiagonal());
    visual.result.health.tracked_points = 300;
    visual.result.health.inlier_ratio = 0.9;
    visual.result.health.brightness = 120.0;
    visual.result.health.contrast = 50.0;
    Eigen::Isometry3d T_final = T;
    T_final.translation().y() += 0.02 * j;
    visual.T_world_camera_final = T_final;
    visual_frames.push_back(visual);
    LidarFrameRecord lidar;
    lidar.t = visual.t;
    lidar.T_odom_lidar = T;
    lidar.pose_reliable = true;
    lidar.information = information.asDiagonal();
    lidar_frames.push_back(lidar);
    online.push_back({visual.t, T});
  }
  SystemConfig config;
  config.mode = RunMode::kFused;
  const PipelineRecords records = recordsOf(visual_frames, lidar_frames, config);
  ASSERT_TRUE(records.estimator_graph);
  ASSERT_EQ(records.estimator_graph->camera_nodes.size(), online.size());
  const Trajectory refined = refineTrajectory(records, config, Eigen::Isometry3d::Identity(), online).trajectory;
  ASSERT_EQ(refined.size(), online.size());
  for (std::size_t j = 0; j < online.size(); ++j)
    EXPECT_LT((refined[j].T_world_frame.translation() - online[j].T_world_frame.translation()).norm(), 0.005) << j;
}

}  // namespace
}  // namespace lvslam::system
