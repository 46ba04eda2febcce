#include "lvslam/system/record_file.h"
#include "lvslam/system/record_fields.h"

#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "lvslam/core/se3.h"
#include "support/temp_dir.h"

namespace lvslam::system {
namespace {

Eigen::Isometry3d pose(double a) {
  return makePose(expSO3(Eigen::Vector3d(a, -0.5 * a, 0.25)), Eigen::Vector3d(a, 2.0 * a, -3.0));
}

Matrix6d matrix(double a) {
  Matrix6d m;
  for (int i = 0; i < 36; ++i) m.data()[i] = a + i;
  return m;
}

bool same(const Eigen::Isometry3d& x, const Eigen::Isometry3d& y) { return x.matrix() == y.matrix(); }

// Every field away from its default, nested ones included.
VisualFrameRecord fullVisualRecord(double t) {
  VisualFrameRecord v;
  v.t = t;
  visual::VisualFrameResult& r = v.result;
  r.timestamp = t + 0.5;
  r.state = visual::TrackingState::kLost;
  r.pose_valid = true;
  r.T_world_camera = pose(t);
  r.map_id = 3;
  r.keyframe = true;
  r.metric = false;
  r.initial_reference = StampedPose{t - 1.0, pose(t + 1.0)};
  r.initial_reference_keyframe = 7;
  r.health = {11, 12, 0.75, 99.5, 31.25, 400, 55};
  r.fusion.pose_information = matrix(t);
  r.fusion.anchor_time = t - 2.0;
  r.fusion.T_new_old = pose(t + 2.0);  // T_world_odom left empty
  r.replay.reference_keyframe = 9;
  r.replay.T_keyframe_camera = pose(t + 3.0);
  r.replay.observations.points = {{4, Eigen::Vector2f(1.5f, 2.5f), 0.25f}, {5, Eigen::Vector2f(3.5f, 4.5f), 0.5f}};
  r.replay.observations.lines = {{6, Eigen::Vector2f(7.f, 8.f), Eigen::Vector2f(9.f, 10.f)}};
  v.T_world_camera_final = pose(t + 4.0);
  v.fusion_lines_added = 13;
  v.keypoint_depths = 14;
  v.extract_ms = 1.25, v.hints_ms = 2.25, v.track_ms = 3.25, v.fusion_apply_ms = 4.25;
  return v;
}

void expectFullVisualRecord(const VisualFrameRecord& v, double t) {
  const VisualFrameRecord e = fullVisualRecord(t);
  EXPECT_EQ(v.t, e.t);
  const visual::VisualFrameResult& r = v.result;
  EXPECT_EQ(r.timestamp, e.result.timestamp);
  EXPECT_EQ(r.state, visual::TrackingState::kLost);
  EXPECT_TRUE(r.pose_valid);
  EXPECT_TRUE(same(r.T_world_camera, e.result.T_world_camera));
  EXPECT_EQ(r.map_id, 3);
  EXPECT_TRUE(r.keyframe);
  EXPECT_FALSE(r.metric);
  ASSERT_TRUE(r.initial_reference);
  EXPECT_EQ(r.initial_reference->t, t - 1.0);
  EXPECT_TRUE(same(r.initial_reference->T_world_frame, e.result.initial_reference->T_world_frame));
  EXPECT_EQ(r.initial_reference_keyframe, 7);
  EXPECT_EQ(r.health.tracked_points, 11);
  EXPECT_EQ(r.health.tracked_lines, 12);
  EXPECT_EQ(r.health.inlier_ratio, 0.75);
  EXPECT_EQ(r.health.brightness, 99.5);
  EXPECT_EQ(r.health.contrast, 31.25);
  EXPECT_EQ(r.health.keypoints, 400);
  EXPECT_EQ(r.health.segments, 55);
  ASSERT_TRUE(r.fusion.pose_information);
  EXPECT_EQ(*r.fusion.pose_information, matrix(t));
  EXPECT_FALSE(r.fusion.T_world_odom);
  EXPECT_EQ(r.fusion.anchor_time, t - 2.0);
  ASSERT_TRUE(r.fusion.T_new_old);
  EXPECT_TRUE(same(*r.fusion.T_new_old, pose(t + 2.0)));
  EXPECT_EQ(r.replay.reference_keyframe, 9);
  EXPECT_TRUE(same(r.replay.T_keyframe_camera, pose(t + 3.0)));
  ASSERT_EQ(r.replay.observations.points.size(), 2u);
  EXPECT_EQ(r.replay.observations.points[1].landmark, 5);
  EXPECT_EQ(r.replay.observations.points[1].pixel, Eigen::Vector2f(3.5f, 4.5f));
  EXPECT_EQ(r.replay.observations.points[1].inv_sigma2, 0.5f);
  ASSERT_EQ(r.replay.observations.lines.size(), 1u);
  EXPECT_EQ(r.replay.observations.lines[0].landmark, 6);
  EXPECT_EQ(r.replay.observations.lines[0].end, Eigen::Vector2f(9.f, 10.f));
  ASSERT_TRUE(v.T_world_camera_final);
  EXPECT_TRUE(same(*v.T_world_camera_final, pose(t + 4.0)));
  EXPECT_FALSE(v.initial_reference_final);
  EXPECT_EQ(v.fusion_lines_added, 13);
  EXPECT_EQ(v.keypoint_depths, 14u);
  EXPECT_EQ(v.extract_ms, 1.25);
  EXPECT_EQ(v.hints_ms, 2.25);
  EXPECT_EQ(v.track_ms, 3.25);
  EXPECT_EQ(v.fusion_apply_ms, 4.25);
}

TEST(RecordFile, AVisualRecordComesBackFieldByField) {
  RecordFile<VisualFrameRecord> file;
  file.push_back(fullVisualRecord(1.0));
  file.push_back(VisualFrameRecord{});
  ASSERT_EQ(file.size(), 2u);
  expectFullVisualRecord(file[0], 1.0);
  EXPECT_FALSE(file[1].result.initial_reference);
  EXPECT_TRUE(file[1].result.replay.observations.points.empty());
}

TEST(RecordFile, LidarScanAndOutputRecordsComeBackFieldByField) {
  LidarFrameRecord l;
  l.t = 2.0;
  l.T_odom_lidar = pose(2.0);
  l.pose_reliable = true;
  l.information = matrix(-3.0);
  l.degenerate = true;
  l.registration = 17;
  l.fusion_lines = {{Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(4, 5, 6)}};
  l.lidar_features = 18, l.lidar_points_refined = 19, l.keypoint_depths = 20;
  l.fusion_ms = 5.5;
  RecordFile<LidarFrameRecord> lidar;
  lidar.push_back(l);
  const LidarFrameRecord r = lidar[0];
  EXPECT_EQ(r.t, 2.0);
  ASSERT_TRUE(r.T_odom_lidar);
  EXPECT_TRUE(same(*r.T_odom_lidar, pose(2.0)));
  EXPECT_TRUE(r.pose_reliable);
  EXPECT_EQ(r.information, matrix(-3.0));
  EXPECT_TRUE(r.degenerate);
  EXPECT_EQ(r.registration, 17u);
  ASSERT_EQ(r.fusion_lines.size(), 1u);
  EXPECT_EQ(r.fusion_lines[0].B, Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(r.lidar_features, 18u);
  EXPECT_EQ(r.lidar_points_refined, 19u);
  EXPECT_EQ(r.keypoint_depths, 20u);
  EXPECT_EQ(r.fusion_ms, 5.5);

  ScanRecord s;
  s.t = 3.0;
  s.status = "degenerate";
  s.features = 22, s.correspondences = 23;
  s.features_per_class = {1, 2, 3, 4, 5, 6};
  s.iterations = 24;
  s.prepare_ms = 6.5, s.register_ms = 7.5;
  RecordFile<ScanRecord> scans;
  scans.push_back(s);
  const ScanRecord back = scans.back();
  EXPECT_EQ(back.t, 3.0);
  EXPECT_EQ(back.status, "degenerate");
  EXPECT_EQ(back.features, 22u);
  EXPECT_EQ(back.correspondences, 23u);
  EXPECT_EQ(back.features_per_class, s.features_per_class);
  EXPECT_EQ(back.iterations, 24);
  EXPECT_EQ(back.prepare_ms, 6.5);
  EXPECT_EQ(back.register_ms, 7.5);

  FrameOutput f;
  f.t = 4.0;
  f.T_world_camera = pose(4.0);
  f.source = OutputSource::kVisual;
  f.problem = "dark \"image\"\n";
  f.fused = true;
  f.gated = {{4.5, FactorSource::kVisual, 30.5, 12.5, "jump"}};
  f.visual_chi_square_per_dof = 0.8, f.lidar_noise_scale = 1.5, f.visual_noise_scale = 2.5;
  f.covariance = matrix(7.0);
  f.latency_ms = 33.0;
  RecordFile<FrameOutput> outputs;
  outputs.push_back(f);
  const FrameOutput o = outputs[0];
  EXPECT_EQ(o.t, 4.0);
  ASSERT_TRUE(o.T_world_camera);
  EXPECT_TRUE(same(*o.T_world_camera, pose(4.0)));
  EXPECT_EQ(o.source, OutputSource::kVisual);
  EXPECT_EQ(o.problem, f.problem);
  EXPECT_TRUE(o.fused);
  ASSERT_EQ(o.gated.size(), 1u);
  EXPECT_EQ(o.gated[0].t, 4.5);
  EXPECT_EQ(o.gated[0].source, FactorSource::kVisual);
  EXPECT_EQ(o.gated[0].chi_square, 30.5);
  EXPECT_EQ(o.gated[0].threshold, 12.5);
  EXPECT_EQ(o.gated[0].reason, "jump");
  EXPECT_EQ(o.visual_chi_square_per_dof, 0.8);
  EXPECT_EQ(o.lidar_noise_scale, 1.5);
  EXPECT_EQ(o.visual_noise_scale, 2.5);
  EXPECT_EQ(o.covariance, matrix(7.0));
  EXPECT_EQ(o.latency_ms, 33.0);
}

// Far more than one write block, read while appending (what is pending is
// written first), by index and in order; changed by update; a copy is its own.
TEST(RecordFile, ManyRecordsReadBackInOrderWhileAppending) {
  RecordFile<VisualFrameRecord> file;
  for (int i = 0; i < 300; ++i) {
    file.push_back(fullVisualRecord(i));
    if (i % 37 == 0) {
      EXPECT_EQ(file[static_cast<std::size_t>(i / 2)].t, i / 2) << i;
    }
  }
  ASSERT_EQ(file.size(), 300u);
  int i = 0;
  for (const VisualFrameRecord& v : file) expectFullVisualRecord(v, i++);
  EXPECT_EQ(i, 300);
  RecordFile<VisualFrameRecord> copy = file;
  file.update([](VisualFrameRecord& v) { v.keypoint_depths = static_cast<std::size_t>(v.t) * 2; });
  EXPECT_EQ(file[123].keypoint_depths, 246u);
  EXPECT_EQ(file[123].t, 123.0);
  EXPECT_EQ(copy[123].keypoint_depths, 14u);
  EXPECT_THROW(static_cast<void>(file[300]), Error);
  EXPECT_FALSE(file.get(300));
  ASSERT_TRUE(file.get(299));
  EXPECT_EQ(file.get(299)->t, 299.0);
}

// The records go to the temporary directory: one that is not there is
// one error naming the variable, not a crash at the first frame.
TEST(RecordFile, AMissingTemporaryDirectoryIsAnErrorNamingIt) {
  const char* before = std::getenv("TMPDIR");
  const std::string saved = before ? before : "";
  ::setenv("TMPDIR", "/nonexistent/lvslam-tmp", 1);
  RecordFile<ScanRecord> file;
  const std::string message = testing::errorMessageOf([&] { file.push_back(ScanRecord{}); });
  if (before) ::setenv("TMPDIR", saved.c_str(), 1);
  else ::unsetenv("TMPDIR");
  EXPECT_NE(message.find("TMPDIR"), std::string::npos) << message;
}

}  // namespace
}  // namespace lvslam::system
