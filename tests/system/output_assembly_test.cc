#include "lvslam/system/output_assembly.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "lvslam/core/se3.h"
#include "support/record_files.h"

namespace lvslam::system {
namespace {

constexpr double kFrameDt = 0.1;

// The true camera: forward at 0.5 m/s while turning and climbing a little.
Eigen::Isometry3d trueCamera(double t) {
  Vector6d xi;
  xi << 0.05, 0.02, 0.5, 0.03, 0.25, -0.04;
  return makePose(expSO3(Eigen::Vector3d(0.2, -0.1, 0.4)), Eigen::Vector3d(2, -1, 0.5)) * expSE3(t * xi);
}

const Eigen::Isometry3d kTCameraLidar =
    makePose(expSO3(Eigen::Vector3d(-1.2, 1.2, -1.2)), Eigen::Vector3d(0.05, -0.1, -0.08));
const Eigen::Isometry3d kTOdomWorld = expSE3((Vector6d() << 3, -2, 1, 0.1, -0.2, 0.7).finished());

Eigen::Isometry3d exactOdomLidar(double t) { return kTOdomWorld * trueCamera(t) * kTCameraLidar; }

double frameTime(std::size_t j) { return 10.0 + kFrameDt * static_cast<double>(j); }

visual::VisualFrameResult healthyResult(double t, int map_id, const Eigen::Isometry3d& T_map_camera) {
  visual::VisualFrameResult r;
  r.timestamp = t;
  r.state = visual::TrackingState::kTracking;
  r.pose_valid = true;
  r.T_world_camera = T_map_camera;
  r.map_id = map_id;
  r.metric = true;
  r.health.tracked_points = 150;
  r.health.tracked_lines = 20;
  r.health.inlier_ratio = 0.9;
  r.health.brightness = 120.0;
  r.health.contrast = 40.0;
  return r;
}

VisualFrameRecord visualRecord(double t, const visual::VisualFrameResult& result) {
  VisualFrameRecord v;
  v.t = t;
  v.result = result;
  return v;
}

// A LiDAR pose registered on both sides, known to 1 mm and 0.05 deg.
LidarFrameRecord lidarRecord(double t, std::optional<Eigen::Isometry3d> T_odom_lidar) {
  LidarFrameRecord l;
  l.t = t;
  l.T_odom_lidar = T_odom_lidar;
  l.pose_reliable = true;
  Vector6d information;
  information << Eigen::Vector3d::Constant(1e6), Eigen::Vector3d::Constant(1.0 / std::pow(0.05 * M_PI / 180.0, 2));
  l.information = information.asDiagonal();
  return l;
}

double translationDiff(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.inverse() * b).translation().norm();
}
double rotationDiff(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) { return rotationAngle(a.inverse() * b); }

// What a test sets up: the per-frame records in memory (the pipeline keeps
// them on disk, record_file.h) and the rest as the pipeline has it.
struct Records {
  std::vector<VisualFrameRecord> visual;
  std::vector<LidarFrameRecord> lidar;
  PipelineRecords other;
};

// The output, with the online output of each frame.
struct Output : SystemOutput {
  std::vector<FrameOutput> frames;
};

// The output as the pipeline makes it: the online output frame by frame
// (online/online_output.h), then the assembly after the run.
Output assembled(const Records& records, const SystemConfig& config, const Eigen::Isometry3d& T_camera_lidar) {
  PipelineRecords pipeline = records.other;
  pipeline.visual = testing::recordFileOf(records.visual);
  pipeline.lidar = testing::recordFileOf(records.lidar);
  const std::unique_ptr<OnlineOutput> online = makeOnlineOutput(config, T_camera_lidar);
  const std::size_t frames = std::max(records.visual.size(), records.lidar.size());
  for (std::size_t j = 0; j < frames; ++j)
    pipeline.online.push_back(online->add(j < records.visual.size() ? &records.visual[j] : nullptr,
                                          j < records.lidar.size() ? &records.lidar[j] : nullptr));
  pipeline.switches = online->switches();
  pipeline.T_world_map = online->mapPlacements();
  Output out{assembleOutput(pipeline, config, T_camera_lidar), testing::vectorOf(pipeline.online)};
  return out;
}

SystemConfig configFor(RunMode mode) {
  SystemConfig c;
  c.mode = mode;
  return c;
}

// ---- lidar mode ----

TEST(AssembleOutput, LidarModeGivesOdometryTimesExtrinsicsExactly) {
  Records records;
  for (std::size_t j = 0; j < 12; ++j) {
    const double t = frameTime(j);
    records.lidar.push_back(lidarRecord(t, j == 0 ? std::nullopt : std::optional(exactOdomLidar(t))));
  }
  const Output out = assembled(records, configFor(RunMode::kLidar), kTCameraLidar);
  ASSERT_EQ(out.frames.size(), 12u);
  EXPECT_TRUE(out.trajectory_is_camera);
  EXPECT_TRUE(out.switches.empty());
  EXPECT_FALSE(out.frames[0].T_world_camera.has_value());  // no LiDAR pose yet
  ASSERT_EQ(out.trajectory.size(), 11u);
  const Eigen::Isometry3d T_lidar_camera = kTCameraLidar.inverse();
  for (std::size_t j = 1; j < 12; ++j) {
    const Eigen::Isometry3d expected = *records.lidar[j].T_odom_lidar * T_lidar_camera;
    ASSERT_TRUE(out.frames[j].T_world_camera.has_value());
    EXPECT_EQ(out.frames[j].source, OutputSource::kLidar);
    EXPECT_TRUE(out.frames[j].T_world_camera->isApprox(expected, 1e-12)) << j;
    EXPECT_EQ(out.trajectory[j - 1].t, frameTime(j));
    EXPECT_TRUE(out.trajectory[j - 1].T_world_frame.isApprox(expected, 1e-12)) << j;
    // ... which is the true camera in the odometry's frame.
    EXPECT_LT(translationDiff(out.trajectory[j - 1].T_world_frame, kTOdomWorld * trueCamera(frameTime(j))), 1e-9);
  }
}

TEST(AssembleOutput, LidarModeWithoutCameraOutputsTheScanTrajectory) {
  Records records;
  for (int k = 0; k < 5; ++k) records.other.T_odom_lidar_scans.push_back({0.1 * k, exactOdomLidar(0.1 * k)});
  const Output out = assembled(records, configFor(RunMode::kLidar), kTCameraLidar);
  EXPECT_FALSE(out.trajectory_is_camera);
  ASSERT_EQ(out.trajectory.size(), 5u);
  for (int k = 0; k < 5; ++k) {
    EXPECT_EQ(out.trajectory[k].t, 0.1 * k);
    EXPECT_TRUE(out.trajectory[k].T_world_frame.isApprox(exactOdomLidar(0.1 * k), 1e-12));
  }
}

TEST(AssembleOutput, FusionLinesAreMovedIntoTheWorldWithTheFramePose) {
  Records records;
  records.lidar.push_back(lidarRecord(frameTime(0), exactOdomLidar(frameTime(0))));
  records.lidar[0].fusion_lines.push_back({Eigen::Vector3d(0.5, -0.2, 3.0), Eigen::Vector3d(0.5, 0.8, 3.1)});
  const Output out = assembled(records, configFor(RunMode::kLidar), kTCameraLidar);
  ASSERT_EQ(out.lines_world.size(), 1u);
  const Eigen::Isometry3d T = *out.frames[0].T_world_camera;
  EXPECT_LT((out.lines_world[0].a - T * Eigen::Vector3d(0.5, -0.2, 3.0)).norm(), 1e-12);
  EXPECT_LT((out.lines_world[0].b - T * Eigen::Vector3d(0.5, 0.8, 3.1)).norm(), 1e-12);
  EXPECT_EQ(out.lines_world[0].r, 255);  // fusion lines are red
  EXPECT_EQ(out.lines_world[0].g, 0);
}

// ---- visual mode ----

// Map 0 starts at frame 5 (first view frame 0), tracks to frame 14, is lost
// over 15..19; map 1 starts at frame 20 with its first view at frame 17.
Records twoVisualMaps(const Eigen::Isometry3d& T_map0_world, const Eigen::Isometry3d& T_map1_world,
                              bool second_metric) {
  Records records;
  for (std::size_t j = 0; j < 30; ++j) {
    const double t = frameTime(j);
    visual::VisualFrameResult r;
    r.timestamp = t;
    if (j >= 5 && j < 15) {
      r = healthyResult(t, 0, T_map0_world * trueCamera(t));
      if (j == 5) r.initial_reference = StampedPose{frameTime(0), T_map0_world * trueCamera(frameTime(0))};
    } else if (j >= 20) {
      r = healthyResult(t, 1, T_map1_world * trueCamera(t));
      r.metric = second_metric;
      if (j == 20) r.initial_reference = StampedPose{frameTime(17), T_map1_world * trueCamera(frameTime(17))};
    } else {
      r.state = j < 5 ? visual::TrackingState::kInitializing : visual::TrackingState::kLost;
      r.map_id = j < 5 ? 0 : 1;
    }
    records.visual.push_back(visualRecord(t, r));
  }
  return records;
}

TEST(AssembleOutput, VisualModeAnchorsTheSecondMapAtTheLastPoseOfTheFirst) {
  const Eigen::Isometry3d map0 = Eigen::Isometry3d::Identity();
  const Eigen::Isometry3d map1 = expSE3((Vector6d() << -5, 4, 2, 0.6, -0.3, 1.2).finished());
  const Output out = assembled(twoVisualMaps(map0, map1, true), configFor(RunMode::kVisual), kTCameraLidar);
  ASSERT_EQ(out.frames.size(), 30u);
  EXPECT_TRUE(out.metric);
  // 10 tracked frames of each map; a map's first view (an earlier frame) had
  // no pose when it was out, and the online output is never revised.
  ASSERT_EQ(out.trajectory.size(), 20u);
  EXPECT_FALSE(out.frames[0].T_world_camera);
  EXPECT_FALSE(out.frames[17].T_world_camera);
  // Map 0 is the world.
  for (std::size_t j : {5, 9, 14}) {
    ASSERT_TRUE(out.frames[j].T_world_camera) << j;
    EXPECT_TRUE(out.frames[j].T_world_camera->isApprox(trueCamera(frameTime(j)), 1e-12)) << j;
  }
  for (std::size_t j : {1, 4, 15, 16, 18, 19}) EXPECT_FALSE(out.frames[j].T_world_camera) << j;
  EXPECT_NE(out.frames[16].problem.find("lost"), std::string::npos) << out.frames[16].problem;
  // Map 1's first view (frame 17) sits where map 0 ended (frame 14): the
  // camera is taken to have stood still while lost.
  const Eigen::Isometry3d last_of_map0 = *out.frames[14].T_world_camera;
  // From there on, map 1's relative motion, whatever its own frame.
  for (std::size_t j = 20; j < 30; ++j) {
    const Eigen::Isometry3d expected = last_of_map0 * trueCamera(frameTime(17)).inverse() * trueCamera(frameTime(j));
    ASSERT_TRUE(out.frames[j].T_world_camera) << j;
    EXPECT_LT(translationDiff(*out.frames[j].T_world_camera, expected), 1e-9) << j;
    EXPECT_LT(rotationDiff(*out.frames[j].T_world_camera, expected), 1e-9) << j;
  }
  // The trajectory is in time order.
  for (std::size_t i = 1; i < out.trajectory.size(); ++i) EXPECT_LT(out.trajectory[i - 1].t, out.trajectory[i].t);
}

// Frames placed on their final keyframes (final_visual_poses.h) need the
// end of the run: the refined trajectory and the visual subsystem's own
// trajectory hold them (unless the configuration asks for the poses as
// tracked); the online output never does.
TEST(AssembleOutput, VisualPosesOnTheFinalKeyframesAreRefinement) {
  Records records = twoVisualMaps(Eigen::Isometry3d::Identity(), Eigen::Isometry3d::Identity(), true);
  const auto shifted = [](std::size_t j) { return expSE3((Vector6d() << 0.01 * j, 0.02, -0.01, 0.001 * j, 0, 0).finished()); };
  for (std::size_t j = 5; j < 15; ++j) records.visual[j].T_world_camera_final = trueCamera(frameTime(j)) * shifted(j);
  records.visual[5].initial_reference_final = trueCamera(frameTime(0)) * shifted(0);
  for (const bool final_poses : {true, false}) {
    SystemConfig config = configFor(RunMode::kVisual);
    config.final_map_poses = final_poses;
    const Output out = assembled(records, config, kTCameraLidar);
    const auto refinedAt = [&](double t) {
      const auto it = std::find_if(out.trajectory_refined.begin(), out.trajectory_refined.end(),
                                   [t](const StampedPose& p) { return p.t == t; });
      EXPECT_NE(it, out.trajectory_refined.end()) << t;
      return it == out.trajectory_refined.end() ? Eigen::Isometry3d::Identity() : it->T_world_frame;
    };
    for (std::size_t j : {5, 9, 14}) {
      ASSERT_TRUE(out.frames[j].T_world_camera) << j;
      EXPECT_TRUE(out.frames[j].T_world_camera->isApprox(trueCamera(frameTime(j)), 1e-12)) << j;  // as tracked
      // Map 0 anchored at its first view, placed the same way.
      const Eigen::Isometry3d expected = final_poses ? trueCamera(frameTime(j)) * shifted(j) : trueCamera(frameTime(j));
      EXPECT_TRUE(refinedAt(frameTime(j)).isApprox(expected, 1e-12)) << j << " final " << final_poses;
    }
    const Trajectory& own = out.visual_maps.at(0);
    ASSERT_EQ(own.size(), 11u);  // first view + 10 tracked
    EXPECT_TRUE(own[0].T_world_frame.isApprox(final_poses ? *records.visual[5].initial_reference_final
                                                          : records.visual[5].result.initial_reference->T_world_frame,
                                              1e-12));
    EXPECT_TRUE(own[4].T_world_frame.isApprox(final_poses ? *records.visual[8].T_world_camera_final
                                                          : records.visual[8].result.T_world_camera,
                                              1e-12));
  }
}

// The lines of an earlier map stay in lines.ply, each map's lines moved
// into the output world with that map's own anchor.
TEST(AssembleOutput, LinesOfEveryVisualMapAreMovedWithTheirMapsAnchor) {
  const Eigen::Isometry3d map1 = expSE3((Vector6d() << -5, 4, 2, 0.6, -0.3, 1.2).finished());
  Records records = twoVisualMaps(Eigen::Isometry3d::Identity(), map1, true);
  const Eigen::Vector3d A_world(1.0, 2.0, 3.0), B_world(1.5, 2.0, 4.0);
  records.other.visual_lines.push_back({A_world, B_world, false, 0, std::nullopt});              // map 0's frame is the world
  records.other.visual_lines.push_back({map1 * A_world, map1 * B_world, true, 1, std::nullopt});  // the same line seen by map 1
  records.other.visual_lines.push_back({A_world, B_world, false, 2, std::nullopt});              // a map the output never used
  const Output out = assembled(records, configFor(RunMode::kVisual), kTCameraLidar);
  ASSERT_EQ(out.lines_world.size(), 2u);
  EXPECT_LT((out.lines_world[0].a - A_world).norm(), 1e-9);
  EXPECT_LT((out.lines_world[0].b - B_world).norm(), 1e-9);
  EXPECT_EQ(out.lines_world[0].g, 255);  // a visual line: green
  // Map 1 is anchored at its first view (frame 17), put where map 0 ended (frame 14).
  const Eigen::Isometry3d T_world_map1 = *out.frames[14].T_world_camera * (map1 * trueCamera(frameTime(17))).inverse();
  EXPECT_LT((out.lines_world[1].a - T_world_map1 * map1 * A_world).norm(), 1e-9);
  EXPECT_LT((out.lines_world[1].b - T_world_map1 * map1 * B_world).norm(), 1e-9);
  EXPECT_EQ(out.lines_world[1].g, 160);  // from fusion: orange
}

// After a loop closure lines.ply stays in map.ply's frame: a line moves as
// the map points added at its time did (the keyframe correction before its
// first keyframe's time; a fusion line, its frame's time).
TEST(AssembleOutput, LoopClosureMovesEachLineWithTheMapOfItsTime) {
  Records records;
  for (std::size_t j = 0; j < 3; ++j) records.lidar.push_back(lidarRecord(frameTime(j), exactOdomLidar(frameTime(j))));
  const Eigen::Vector3d A(0.5, -0.2, 3.0), B(0.5, 0.8, 3.1);
  records.lidar[2].fusion_lines.push_back({A, B});
  loop::LoopClosureResult loop;
  loop.keyframe_times = {frameTime(0), frameTime(1) + 0.01};
  loop.T_odom_lidar = {exactOdomLidar(frameTime(0)), exactOdomLidar(frameTime(1))};
  const Eigen::Isometry3d D = expSE3((Vector6d() << 0.3, -0.1, 0.2, 0.02, -0.05, 0.1).finished());
  loop.T_odom_lidar_corrected = {loop.T_odom_lidar[0], D * loop.T_odom_lidar[1]};
  loop.solved = true;
  records.other.loop = loop;
  // Lines of visual map 0 (placed at the world origin below): one first
  // seen before the corrected keyframe, one after it, one never observed.
  records.other.visual_lines.push_back({A, B, false, 0, frameTime(1)});
  records.other.visual_lines.push_back({A, B, false, 0, frameTime(2)});
  records.other.visual_lines.push_back({A, B, false, 0, std::nullopt});
  SystemConfig config = configFor(RunMode::kLidar);
  PipelineRecords placed = records.other;
  placed.lidar = testing::recordFileOf(records.lidar);
  placed.T_world_map[0] = Eigen::Isometry3d::Identity();
  const std::unique_ptr<OnlineOutput> online = makeOnlineOutput(config, kTCameraLidar);
  for (const LidarFrameRecord& l : records.lidar) placed.online.push_back(online->add(nullptr, &l));
  const SystemOutput out = assembleOutput(placed, config, kTCameraLidar);
  ASSERT_EQ(out.lines_world.size(), 4u);
  const Eigen::Isometry3d T = *placed.online[2].T_world_camera;
  EXPECT_LT((out.lines_world[0].a - D * T * A).norm(), 1e-9);  // the fusion line of frame 2, after the keyframe
  EXPECT_LT((out.lines_world[0].b - D * T * B).norm(), 1e-9);
  EXPECT_LT((out.lines_world[1].a - A).norm(), 1e-9);  // first seen before it: the first keyframe's (none) correction
  EXPECT_LT((out.lines_world[2].a - D * A).norm(), 1e-9);
  EXPECT_LT((out.lines_world[2].b - D * B).norm(), 1e-9);
  EXPECT_LT((out.lines_world[3].a - A).norm(), 1e-9);  // no time: left where the map put it
}

TEST(AssembleOutput, VisualModeIsNotMetricWhenAnyMapIsNot) {
  const Eigen::Isometry3d I = Eigen::Isometry3d::Identity();
  EXPECT_FALSE(assembled(twoVisualMaps(I, I, false), configFor(RunMode::kVisual), kTCameraLidar).metric);
}

// ---- fused mode ----

// The visual estimate drifts 1 mm per frame along the camera x axis: small
// enough to agree with the LiDAR, large enough to tell whose motion the
// output follows.
Eigen::Isometry3d driftingVisual(const Eigen::Isometry3d& T_map_world, std::size_t j) {
  const Eigen::Isometry3d drift = makePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.001 * j, 0.0, 0.0));
  return T_map_world * trueCamera(frameTime(j)) * drift;
}

struct FusedScenario {
  Records records;
  std::size_t blackout_begin = 20, blackout_end = 30;  // frames [begin, end) are black
};

// Healthy vision in map 0, a blackout, then a new map 1; the LiDAR is exact throughout.
const Eigen::Isometry3d kTMap0World = expSE3((Vector6d() << 1, 2, 3, 0.1, 0.2, 0.3).finished());
const Eigen::Isometry3d kTMap1World = expSE3((Vector6d() << -4, 0, 1, 0.5, -0.2, 0.0).finished());

FusedScenario blackoutScenario(std::size_t frames) {
  FusedScenario s;
  const Eigen::Isometry3d& map0 = kTMap0World;
  const Eigen::Isometry3d& map1 = kTMap1World;
  for (std::size_t j = 0; j < frames; ++j) {
    const double t = frameTime(j);
    visual::VisualFrameResult r;
    if (j < s.blackout_begin) {
      r = healthyResult(t, 0, driftingVisual(map0, j));
    } else if (j < s.blackout_end) {
      r.state = visual::TrackingState::kLost;
      r.map_id = 0;
      r.health.brightness = 0.0;  // black image
      r.health.contrast = 0.0;
    } else {
      r = healthyResult(t, 1, driftingVisual(map1, j));
    }
    s.records.visual.push_back(visualRecord(t, r));
    s.records.lidar.push_back(lidarRecord(t, exactOdomLidar(t)));
  }
  return s;
}

// Whose motion each output step follows: the visual map's while vision stays
// in use in the same map, the LiDAR's otherwise (including the frame of a
// switch, where the visual map is re-anchored, so there is no jump).
void expectStepsFollowTheSource(const Records& records, const Output& out) {
  const Eigen::Isometry3d T_lidar_camera = kTCameraLidar.inverse();
  for (std::size_t j = 1; j < out.frames.size(); ++j) {
    ASSERT_TRUE(out.frames[j - 1].T_world_camera && out.frames[j].T_world_camera) << j;
    const Eigen::Isometry3d step = out.frames[j - 1].T_world_camera->inverse() * *out.frames[j].T_world_camera;
    const auto& v0 = records.visual[j - 1].result;
    const auto& v1 = records.visual[j].result;
    const bool visual_step = out.frames[j - 1].source == OutputSource::kVisual &&
                             out.frames[j].source == OutputSource::kVisual && v0.map_id == v1.map_id;
    const Eigen::Isometry3d expected =
        visual_step ? v0.T_world_camera.inverse() * v1.T_world_camera
                    : T_lidar_camera.inverse() * records.lidar[j - 1].T_odom_lidar->inverse() *
                          *records.lidar[j].T_odom_lidar * T_lidar_camera;
    EXPECT_LT(translationDiff(step, expected), 1e-9) << "frame " << j << (visual_step ? " (visual)" : " (lidar)");
    EXPECT_LT(rotationDiff(step, expected), 1e-9) << j;
    // No jump: every step is one frame's true motion, up to the drift (1 mm
    // per frame, plus the turn of the accumulated drift: < 3 mm here).
    const Eigen::Isometry3d true_step = trueCamera(frameTime(j - 1)).inverse() * trueCamera(frameTime(j));
    EXPECT_LT(translationDiff(step, true_step), 3e-3) << j;
  }
}

// Each subsystem's own estimate is kept apart from the output: the visual
// poses per map in that map's frame (first view included), and the LiDAR
// odometry carried to the camera at every frame it has a pose.
TEST(AssembleOutput, FusedKeepsEachSubsystemsOwnTrajectory) {
  FusedScenario s = blackoutScenario(40);
  s.records.visual[30].result.initial_reference = StampedPose{frameTime(27), Eigen::Isometry3d::Identity()};
  s.records.lidar[5].T_odom_lidar.reset();  // a frame the LiDAR has no pose for
  const Output out = assembled(s.records, configFor(RunMode::kFused), kTCameraLidar);
  ASSERT_EQ(out.visual_maps.size(), 2u);
  const Trajectory& map0 = out.visual_maps.at(0);
  const Trajectory& map1 = out.visual_maps.at(1);
  ASSERT_EQ(map0.size(), s.blackout_begin);
  ASSERT_EQ(map1.size(), 40 - s.blackout_end + 1);
  for (std::size_t j = 0; j < s.blackout_begin; ++j) {
    EXPECT_EQ(map0[j].t, frameTime(j));
    EXPECT_TRUE(map0[j].T_world_frame.isApprox(s.records.visual[j].result.T_world_camera, 1e-12)) << j;
  }
  EXPECT_EQ(map1.front().t, frameTime(27));  // the first view, before the frame that initialised the map
  EXPECT_TRUE(map1.front().T_world_frame.isApprox(Eigen::Isometry3d::Identity(), 1e-12));
  EXPECT_TRUE(map1.back().T_world_frame.isApprox(s.records.visual[39].result.T_world_camera, 1e-12));
  ASSERT_EQ(out.lidar_camera.size(), 39u);
  for (const StampedPose& p : out.lidar_camera) {
    EXPECT_NE(p.t, frameTime(5));
    EXPECT_LT(translationDiff(p.T_world_frame, kTOdomWorld * trueCamera(p.t)), 1e-9) << p.t;
  }
  // Visual mode has no LiDAR trajectory of its own.
  EXPECT_TRUE(assembled(s.records, configFor(RunMode::kVisual), kTCameraLidar).lidar_camera.empty());
}

// The paper's output (ablation paper-output): the visual pose itself while vision is trusted.
SystemConfig paperOutputConfig() {
  SystemConfig c = configFor(RunMode::kFused);
  c.paper_output = true;
  return c;
}

// Waiting for the first map is no failure: vision enters at its first
// healthy frame, no streak (that is for coming back, next test).
TEST(AssembleOutput, FusedUsesTheFirstVisualMapFromItsFirstHealthyFrame) {
  FusedScenario s = blackoutScenario(20);
  for (std::size_t j = 0; j < 3; ++j) {  // still looking for the first map, on good images
    visual::VisualFrameResult& r = s.records.visual[j].result;
    r.state = visual::TrackingState::kInitializing;
    r.pose_valid = false;
    r.health.tracked_points = 0;
    r.health.tracked_lines = 0;
    r.health.inlier_ratio = 0.0;
  }
  SystemConfig config = paperOutputConfig();
  config.detection.frames_to_recover = 6;
  const Output out = assembled(s.records, config, kTCameraLidar);
  ASSERT_EQ(out.frames.size(), 20u);
  for (std::size_t j = 0; j < 3; ++j) {
    EXPECT_EQ(out.frames[j].source, OutputSource::kLidar) << j;
    EXPECT_NE(out.frames[j].problem.find("initializing"), std::string::npos) << j;
  }
  for (std::size_t j = 3; j < 20; ++j) EXPECT_EQ(out.frames[j].source, OutputSource::kVisual) << j;
  ASSERT_EQ(out.switches.size(), 1u);
  EXPECT_EQ(out.switches[0].t, frameTime(3));
  EXPECT_EQ(out.switches[0].to, OutputSource::kVisual);
  // The LiDAR starts the output: the odometry frame, carried to the camera.
  EXPECT_TRUE(out.frames[0].T_world_camera->isApprox(exactOdomLidar(frameTime(0)) * kTCameraLidar.inverse(), 1e-12));
  expectStepsFollowTheSource(s.records, out);
}

TEST(AssembleOutput, FusedBlackoutSwitchesToLidarAtOnceAndBackWithoutJumps) {
  FusedScenario s = blackoutScenario(50);
  SystemConfig config = paperOutputConfig();
  config.detection.frames_to_recover = 5;
  const Output out = assembled(s.records, config, kTCameraLidar);
  ASSERT_EQ(out.frames.size(), 50u);
  ASSERT_EQ(out.switches.size(), 3u);
  EXPECT_EQ(out.switches[0].to, OutputSource::kVisual);
  EXPECT_EQ(out.switches[0].t, frameTime(0));  // the first map, healthy from the start
  // The first black frame hands over to the LiDAR, saying why.
  EXPECT_EQ(out.switches[1].to, OutputSource::kLidar);
  EXPECT_EQ(out.switches[1].t, frameTime(s.blackout_begin));
  EXPECT_NE(out.switches[1].reason.find("dark"), std::string::npos) << out.switches[1].reason;
  EXPECT_NE(out.frames[s.blackout_begin + 3].problem.find("dark"), std::string::npos);
  // Back on the new map after five healthy frames with known motion: the
  // first new frame has none (the previous one had no pose), so 30..34.
  EXPECT_EQ(out.switches[2].to, OutputSource::kVisual);
  EXPECT_EQ(out.switches[2].t, frameTime(s.blackout_end + 4));
  for (std::size_t j = s.blackout_begin; j < s.blackout_end + 4; ++j)
    EXPECT_EQ(out.frames[j].source, OutputSource::kLidar) << j;
  expectStepsFollowTheSource(s.records, out);
}

TEST(AssembleOutput, FusedNeverUsesANonMetricVisualMap) {
  FusedScenario s = blackoutScenario(40);
  for (VisualFrameRecord& v : s.records.visual) v.result.metric = false;
  SystemConfig config = configFor(RunMode::kFused);
  config.detection.frames_to_recover = 2;
  const Output out = assembled(s.records, config, kTCameraLidar);
  EXPECT_TRUE(out.switches.empty());
  for (std::size_t j = 0; j < out.frames.size(); ++j) EXPECT_EQ(out.frames[j].source, OutputSource::kLidar) << j;
  EXPECT_NE(out.frames[10].problem.find("metric"), std::string::npos) << out.frames[10].problem;
  // All LiDAR (and the weak motion model): the true camera in the odometry frame.
  for (std::size_t j = 0; j < out.frames.size(); ++j)
    EXPECT_LT(translationDiff(*out.frames[j].T_world_camera, kTOdomWorld * trueCamera(frameTime(j))), 1e-4) << j;
  // Refined over the whole run: no further from the truth.
  ASSERT_EQ(out.trajectory_refined.size(), out.trajectory.size());
  for (std::size_t j = 0; j < out.frames.size(); ++j)
    EXPECT_LT(translationDiff(out.trajectory_refined[j].T_world_frame, kTOdomWorld * trueCamera(frameTime(j))), 1e-4) << j;
}

TEST(AssembleOutput, FusedSkipsFramesBeforeTheFirstLidarPose) {
  FusedScenario s = blackoutScenario(10);
  s.records.lidar[0].T_odom_lidar.reset();
  s.records.lidar[1].T_odom_lidar.reset();
  const Output out = assembled(s.records, configFor(RunMode::kFused), kTCameraLidar);
  EXPECT_FALSE(out.frames[0].T_world_camera);
  EXPECT_FALSE(out.frames[1].T_world_camera);
  ASSERT_TRUE(out.frames[2].T_world_camera);
  EXPECT_EQ(out.trajectory.size(), 8u);
  EXPECT_TRUE(out.frames[2].T_world_camera->isApprox(exactOdomLidar(frameTime(2)) * kTCameraLidar.inverse(), 1e-12));
}

}  // namespace
}  // namespace lvslam::system
