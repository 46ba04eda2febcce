// The bridge between the LiDAR subsystem's public face and the fusion
// framework, through a real LidarOdometry on simulated sweeps.
#include "lvslam/fusion/lidar_bridge.h"

#include <set>

#include <gtest/gtest.h>

#include "lvslam/fusion/fusion_step.h"
#include "lvslam/sim/camera_renderer.h"
#include "lvslam/sim/lidar_simulator.h"
#include "lvslam/sim/scenario.h"

namespace lvslam::fusion {
namespace {

struct SimRig {
  sim::Scenario scenario = sim::makeScenario("room", {});
  sim::LidarSimulator lidar{scenario};
  double sweepStart(int k) const { return scenario.lidar.start_offset + 4.0 + k * lidar.sweepDuration(); }
};

// Registers `registered` sweeps, then prepares one more.
void runUntilPrepared(const SimRig& rig, lidar::LidarOdometry& odometry, int registered) {
  for (int k = 0; k < registered; ++k) odometry.process(rig.lidar.scanLidar(rig.sweepStart(k)));
  odometry.prepare(rig.lidar.scanLidar(rig.sweepStart(registered)));
}

// Every frame the fusion can name points of: the recent ones and the prepared one.
std::vector<lidar::FeatureFrame> visibleFrames(const lidar::LidarOdometry& odometry) {
  std::vector<lidar::FeatureFrame> frames(odometry.recentFrames().begin(), odometry.recentFrames().end());
  frames.push_back(odometry.currentFrame());
  return frames;
}

// Points whose direction or flag differ between two snapshots, by id.
std::set<lidar::FeatureId> changedIds(const std::vector<lidar::FeatureFrame>& before,
                                      const std::vector<lidar::FeatureFrame>& after) {
  std::set<lidar::FeatureId> changed;
  EXPECT_EQ(before.size(), after.size());
  for (std::size_t f = 0; f < std::min(before.size(), after.size()); ++f) {
    EXPECT_EQ(before[f].points.size(), after[f].points.size());
    for (std::size_t i = 0; i < before[f].points.size(); ++i) {
      const auto& a = before[f].points[i];
      const auto& b = after[f].points[i];
      EXPECT_EQ(a.p, b.p);  // positions and classes never change
      EXPECT_EQ(a.cls, b.cls);
      if (a.direction != b.direction || a.refined != b.refined) changed.insert(before[f].id(i));
    }
  }
  return changed;
}

TEST(LidarBridge, ClassesMapToShapesAndIdsToTheFrame) {
  EXPECT_EQ(shapeOf(lidar::FeatureClass::kGround), FeatureShape::kPlanar);
  EXPECT_EQ(shapeOf(lidar::FeatureClass::kFacade), FeatureShape::kPlanar);
  EXPECT_EQ(shapeOf(lidar::FeatureClass::kRoof), FeatureShape::kPlanar);
  EXPECT_EQ(shapeOf(lidar::FeatureClass::kPillar), FeatureShape::kLinear);
  EXPECT_EQ(shapeOf(lidar::FeatureClass::kBeam), FeatureShape::kLinear);
  EXPECT_EQ(shapeOf(lidar::FeatureClass::kVertex), FeatureShape::kOther);
  lidar::FeatureFrame frame;
  frame.seq = 7;
  frame.timestamp = 12.5;
  frame.points.resize(3);
  frame.points[1].cls = lidar::FeatureClass::kPillar;
  frame.points[1].p = {1.0f, 2.0f, 3.0f};
  const auto features = toTimedFeatures(frame);
  ASSERT_EQ(features.size(), 3u);
  EXPECT_EQ(features[1].id, lidar::makeFeatureId(7, 1));
  EXPECT_EQ(features[1].shape, FeatureShape::kLinear);
  EXPECT_EQ(features[1].t, 12.5);
  EXPECT_EQ(features[1].p_lidar, Eigen::Vector3d(1.0, 2.0, 3.0));
}

TEST(LidarBridge, DirectionUpdateChangesExactlyTheNamedLinearPoints) {
  const SimRig rig;
  lidar::LidarOdometry odometry({});
  runUntilPrepared(rig, odometry, 3);
  const auto before = visibleFrames(odometry);
  // Name linear points of the prepared and of a recent frame, plus planar
  // points and an unknown id, which must be left alone.
  std::vector<lidar::FeatureId> ids;
  std::set<lidar::FeatureId> linear;
  for (const lidar::FeatureFrame* frame : {&before.back(), &before.front()}) {
    int taken_linear = 0, taken_planar = 0;
    for (std::size_t i = 0; i < frame->points.size(); ++i) {
      const bool is_linear = lidar::isLinear(frame->points[i].cls);
      if (is_linear && taken_linear < 5) ++taken_linear, ids.push_back(frame->id(i)), linear.insert(frame->id(i));
      if (!is_linear && taken_planar < 3) ++taken_planar, ids.push_back(frame->id(i));
    }
  }
  ids.push_back(lidar::makeFeatureId(9999, 0));
  ASSERT_GE(linear.size(), 6u) << "the simulated room should give linear points in both frames";
  const Eigen::Vector3d d_world = Eigen::Vector3d(1.0, 2.0, 3.0).normalized();
  const LinearDirectionUpdate update{ids, d_world};
  EXPECT_EQ(applyDirectionUpdates(odometry, std::span(&update, 1)), linear.size());

  const auto after = visibleFrames(odometry);
  EXPECT_EQ(changedIds(before, after), linear);
  for (const auto& frame : after)
    for (std::size_t i = 0; i < frame.points.size(); ++i)
      if (linear.count(frame.id(i))) {
        const Eigen::Vector3d d = frame.T_world_lidar.linear() * frame.points[i].direction.cast<double>();
        EXPECT_LT((d - d_world).norm(), 1e-6);
        EXPECT_TRUE(frame.points[i].refined);
      }
}

TEST(LidarBridge, FusionStepFeedbackChangesExactlyTheLinearPointsOfItsLines) {
  const SimRig rig;
  const sim::CameraRenderer renderer(rig.scenario);
  lidar::LidarOdometry odometry({});
  FusionStep step(rig.scenario.camera.camera, rig.scenario.rig.T_camera_lidar(), FusionConfig{});
  std::size_t updates_seen = 0;
  visual::LineExtractorConfig lines;
  lines.compute_descriptors = false;
  lines.min_length_ratio = 30.0 / 480.0;
  visual::LineExtractor extractor(lines);
  // Several frames: not every one has a linear-case line.
  for (int k = 0; k < 10; ++k) {
    odometry.prepare(rig.lidar.scanLidar(rig.sweepStart(k)));
    if (k >= 4) {
      step.loadScans(odometry);
      const double t = rig.sweepStart(k) + 0.05;
      std::vector<visual::RawSegment> raw;
      cv::Mat unused;
      extractor.extract(renderer.renderImage(t), raw, unused);
      const auto before = visibleFrames(odometry);
      const FusionFrameOutput out = step.processImage(t, toImageSegments(raw), odometry);
      std::set<lidar::FeatureId> expected;
      for (const auto& u : out.result.lidar_updates) expected.insert(u.ids.begin(), u.ids.end());
      EXPECT_EQ(changedIds(before, visibleFrames(odometry)), expected);
      updates_seen += out.result.lidar_updates.size();
    }
    odometry.registerScan();
  }
  EXPECT_GT(updates_seen, 0u);
}

}  // namespace
}  // namespace lvslam::fusion
