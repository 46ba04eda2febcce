// The visual worker returns and records what its header says, on the first
// second of a simulated room at twice its speed (made once into the test cache).
#include "lvslam/system/visual_worker.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <optional>

#include "lvslam/core/error.h"
#include "lvslam/core/yaml_config.h"
#include "lvslam/io/recording.h"
#include "system/sim_cache.h"

namespace lvslam::system {
namespace {

// Twice the room's speed: a map starts after a few frames.
std::string fastRoom() { return lvslam::testing::cachedRoom(2.0, 1, 2.0); }

SystemConfig simConfig() {
  SystemConfig config = loadSystemConfig(YamlConfig::loadFile(std::string(LVSLAM_SOURCE_DIR) + "/config/sim.yaml"));
  config.deterministic = true;
  return config;
}

// What track() returned and what the worker's subsystem said right after.
struct Tracked {
  double t = 0.0;
  std::vector<Eigen::Vector2d> returned;
  bool pose_valid = false, keyframe = false;
  std::vector<Eigen::Vector2d> keypoints;  // slam().keypointPixels()
  std::size_t stored_depths = 0;           // finite depths of the map's newest keyframe
};

// Feeds the recording's scans and its images from `from` to `to` seconds
// after the first image, in order; `after_track` runs after each track()
// (e.g. to apply a fusion answer).
std::vector<Tracked> feed(VisualWorker& worker, double from, double to,
                          const std::function<void(VisualWorker&, const Tracked&)>& after_track = {}) {
  RecordingRequest request;
  request.sequence_dir = fastRoom();
  Recording recording = openRecording(request);
  const Calibration calibration = recording.source->calibration();
  visual::FeatureExtractor extractor(simConfig().visual.modules.features, *calibration.camera);
  std::vector<Tracked> tracked;
  std::optional<double> first;
  while (auto data = recording.source->next()) {
    if (auto* scan = std::get_if<LidarScan>(&*data)) {
      worker.addScan(std::make_shared<const LidarScan>(std::move(*scan)));
      continue;
    }
    const ImageFrame& image = std::get<ImageFrame>(*data);
    if (!first) first = image.timestamp;
    if (image.timestamp < *first + from) continue;
    if (image.timestamp > *first + to) break;
    Tracked t;
    t.t = image.timestamp;
    t.returned = worker.track(visual::extractImage(extractor, image), 1.5 + tracked.size());
    t.pose_valid = worker.lastFrame().result.pose_valid;
    t.keyframe = worker.slam().currentIsKeyframe();
    t.keypoints = worker.slam().keypointPixels();
    if (!worker.slam().map().keyframes().empty())
      t.stored_depths = depthCount(worker.slam().map().keyframes().rbegin()->second.keypoint_depth);
    if (after_track) after_track(worker, t);
    tracked.push_back(std::move(t));
  }
  return tracked;
}

Calibration calibrationOfTheRoom() {
  RecordingRequest request;
  request.sequence_dir = fastRoom();
  return openRecording(request).source->calibration();
}

// A fusion answer with one line, for the frame's first segment, 3 m ahead.
FusionAnswer oneFusionLine() {
  FusionAnswer answer;
  fusion::FusionLine line;
  line.segment_index = 0;
  line.A = Eigen::Vector3d(-0.5, 0.2, 3.0);
  line.B = Eigen::Vector3d(0.5, 0.2, 3.0);
  line.direction = Eigen::Vector3d::UnitX();
  answer.result.lines.push_back(line);
  return answer;
}

// Applies oneFusionLine() after every frame that has a segment.
void applyOneLine(VisualWorker& worker, const Tracked&) {
  if (!worker.slam().lineSegments().empty()) worker.applyFusion(oneFusionLine());
}

TEST(VisualWorker, WithoutACameraItRefusesToStart) {
  const Calibration no_camera;
  EXPECT_THROW(VisualWorker(simConfig(), no_camera, true), Error);
  EXPECT_THROW(VisualWorker(simConfig(), no_camera, false), Error);
}

TEST(VisualWorker, KeyframeDepthsFromScansAreRecordedAndNothingIsAskedOfTheFusionFramework) {
  const SystemConfig config = simConfig();  // fused, keypoint_depth_source: scans
  ASSERT_EQ(config.keypoint_depth_source, KeypointDepthSource::kScans);
  VisualWorker worker(config, calibrationOfTheRoom(), true);
  const std::vector<Tracked> tracked = feed(worker, 0.6, 1.45, applyOneLine);
  ASSERT_EQ(worker.frameCount(), tracked.size());
  const RecordFile<VisualFrameRecord> frames = worker.takeFrames();
  ASSERT_EQ(frames.size(), tracked.size());
  int keyframes = 0, with_depths = 0;
  for (std::size_t i = 0; i < tracked.size(); ++i) {
    const VisualFrameRecord record = frames[i];
    EXPECT_EQ(record.t, tracked[i].t);
    EXPECT_EQ(record.extract_ms, 1.5 + i);
    EXPECT_TRUE(tracked[i].returned.empty()) << "frame " << i;
    // The fusion line becomes a landmark of a frame with a pose; without one
    // the answer is ignored.
    EXPECT_EQ(record.fusion_lines_added, tracked[i].pose_valid ? 1 : 0) << "frame " << i;
    if (tracked[i].pose_valid && tracked[i].keyframe) {
      // The depths counted are those the keyframe stores.
      ++keyframes;
      EXPECT_EQ(record.keypoint_depths, tracked[i].stored_depths) << "frame " << i;
      with_depths += record.keypoint_depths > 0 ? 1 : 0;
    } else {
      EXPECT_EQ(record.keypoint_depths, 0u) << "frame " << i;
    }
  }
  EXPECT_GE(keyframes, 2);
  EXPECT_GE(with_depths, 1);
}

// A tracked frame's inliers are kept for the whole run only where the
// refinement optimises the frame again on them (visual mode, the paper's
// output); the fused estimator's refinement replays the frames as tracked.
std::size_t framesKeepingObservations(const SystemConfig& config) {
  VisualWorker worker(config, calibrationOfTheRoom(), true);
  feed(worker, 0.6, 1.45);
  std::size_t kept = 0;
  for (const VisualFrameRecord& record : worker.takeFrames())
    kept += record.result.replay.observations.points.empty() ? 0 : 1;
  return kept;
}

TEST(VisualWorker, KeepsEachFramesInliersOnlyWhenTheRefinementRelocatesFrames) {
  SystemConfig visual = simConfig();
  visual.mode = RunMode::kVisual;
  SystemConfig paper = simConfig();
  paper.paper_output = true;
  SystemConfig fused = simConfig();
  ASSERT_EQ(fused.mode, RunMode::kFused);
  ASSERT_FALSE(fused.paper_output);
  EXPECT_GE(framesKeepingObservations(visual), 3u);
  EXPECT_GE(framesKeepingObservations(paper), 3u);
  EXPECT_EQ(framesKeepingObservations(fused), 0u);
  paper.final_map_relocation = false;
  EXPECT_EQ(framesKeepingObservations(paper), 0u);
}

TEST(VisualWorker, WithDepthsFromFeaturesAKeyframeReturnsItsKeypointsForTheFusionFramework) {
  SystemConfig config = simConfig();
  config.keypoint_depth_source = KeypointDepthSource::kFeatures;
  config.fusion_lines_in_tracking = false;  // ablation "fusion-lines": answers bring no landmark
  VisualWorker worker(config, calibrationOfTheRoom(), true);
  const std::vector<Tracked> tracked = feed(worker, 0.6, 1.45, applyOneLine);
  const RecordFile<VisualFrameRecord> frames = worker.takeFrames();
  int keyframes = 0;
  for (std::size_t i = 0; i < tracked.size(); ++i) {
    const bool keyframe = tracked[i].pose_valid && tracked[i].keyframe;
    keyframes += keyframe ? 1 : 0;
    EXPECT_EQ(tracked[i].returned.empty(), !keyframe) << "frame " << i;
    if (keyframe) {
      ASSERT_EQ(tracked[i].returned.size(), tracked[i].keypoints.size());
      for (std::size_t k = 0; k < tracked[i].returned.size(); ++k)
        EXPECT_EQ(tracked[i].returned[k], tracked[i].keypoints[k]);
    }
    EXPECT_EQ(frames[i].keypoint_depths, 0u);  // none from the raw scans
    EXPECT_EQ(frames[i].fusion_lines_added, 0);
  }
  EXPECT_GE(keyframes, 2);
}

}  // namespace
}  // namespace lvslam::system
