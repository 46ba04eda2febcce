// The online output is causal: the pose of frame j comes from data up to
// frame j and the LiDAR sweeps around its time (a sweep is registered after
// the fusion framework has seen the camera frames of its sweep), so a
// recording cut two sweeps after frame j gives frame j, and every frame
// before it, the same bytes as the whole recording does.
#include <gtest/gtest.h>

#include "lvslam/core/yaml_config.h"
#include "lvslam/io/recording.h"
#include "lvslam/system/system_pipeline.h"
#include "support/record_files.h"
#include "system/sim_cache.h"

namespace lvslam::system {
namespace {

// Passes its source's items through, until an image after `cut`: from then
// on only the scans needed to pose the frames before the cut (one sweep
// past it), then the end.
class CutSource : public SensorSource {
 public:
  CutSource(SensorSource& source, double cut, double sweep) : source_(source), cut_(cut), sweep_(sweep) {}
  std::optional<SensorData> next() override {
    while (auto data = source_.next()) {
      if (const auto* image = std::get_if<ImageFrame>(&*data)) {
        if (image->timestamp > cut_) continue;
      } else if (std::get<LidarScan>(*data).timestamp > cut_ + 2.0 * sweep_) {
        return std::nullopt;
      }
      return data;
    }
    return std::nullopt;
  }
  Calibration calibration() const override { return source_.calibration(); }
  bool hasCamera() const override { return source_.hasCamera(); }
  bool hasLidar() const override { return source_.hasLidar(); }

 private:
  SensorSource& source_;
  double cut_, sweep_;
};

std::vector<FrameOutput> onlineOutput(RunMode mode, std::optional<double> cut) {
  const std::string dir = lvslam::testing::cachedRoom(5.0, 2);
  SystemConfig config = loadSystemConfig(YamlConfig::loadFile(std::string(LVSLAM_SOURCE_DIR) + "/config/sim.yaml"));
  config.mode = mode;
  config.deterministic = true;
  RecordingRequest request;
  request.sequence_dir = dir;
  Recording recording = openRecording(request);
  if (!cut) return lvslam::testing::vectorOf(runPipeline(*recording.source, config, {}).online);
  CutSource source(*recording.source, *cut, 0.1);
  return lvslam::testing::vectorOf(runPipeline(source, config, {}).online);
}

class OnlineCausality : public ::testing::TestWithParam<RunMode> {};

TEST_P(OnlineCausality, PosesUpToTheCutAreTheSameWithoutTheRest) {
  const std::vector<FrameOutput> whole = onlineOutput(GetParam(), std::nullopt);
  ASSERT_FALSE(whole.empty());
  const double cut = whole.front().t + 3.0;
  const std::vector<FrameOutput> part = onlineOutput(GetParam(), cut);
  std::size_t compared = 0, with_pose = 0;
  for (std::size_t j = 0; j < part.size() && part[j].t <= cut - 0.2; ++j) {
    ASSERT_LT(j, whole.size());
    ASSERT_EQ(part[j].t, whole[j].t);
    ASSERT_EQ(part[j].T_world_camera.has_value(), whole[j].T_world_camera.has_value()) << "frame " << j;
    if (part[j].T_world_camera) {
      EXPECT_EQ(part[j].T_world_camera->matrix(), whole[j].T_world_camera->matrix()) << "frame " << j;
      ++with_pose;
    }
    ++compared;
  }
  EXPECT_GE(compared, 38u);  // 15 Hz for 2.8 s
  EXPECT_GE(with_pose, 20u);  // vision starts within the first second
}

INSTANTIATE_TEST_SUITE_P(Modes, OnlineCausality, ::testing::Values(RunMode::kFused, RunMode::kLidar, RunMode::kVisual),
                         [](const ::testing::TestParamInfo<RunMode>& info) { return std::string(runModeName(info.param)); });

}  // namespace
}  // namespace lvslam::system
