// runPipeline's failure handling on small hand-made data: whatever fails
// (the source, or a subsystem on one thread while the other waits for it),
// the error reaches the caller once every thread has stopped, never a hang.
#include "lvslam/system/system_pipeline.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <future>

#include <gtest/gtest.h>

#include "lvslam/core/error.h"
#include "lvslam/core/se3.h"

namespace lvslam::system {
namespace {

constexpr int kImageWidth = 160, kImageHeight = 120;

// A LiDAR at the middle of a 10 x 8 x 3 m box room moving along x at
// 0.3 m/s: each ray hits the nearest wall (16 rings, 1 degree columns).
LidarScan boxRoomScan(double t) {
  LidarScan scan;
  scan.timestamp = t;
  scan.has_time = true;
  scan.has_ring = true;
  const Eigen::Vector3d lo(-5.0, -4.0, -1.2), hi(5.0, 4.0, 1.8);
  const double x = 0.3 * t;
  constexpr int kRings = 16, kColumns = 360;
  for (int c = 0; c < kColumns; ++c) {
    const double azimuth = 2.0 * M_PI * c / kColumns;
    const float time = static_cast<float>(0.1 * c / kColumns);
    const Eigen::Vector3d origin(x + 0.3 * time, 0.0, 0.0);
    for (int r = 0; r < kRings; ++r) {
      const double elevation = (-15.0 + 2.0 * r) * M_PI / 180.0;
      const Eigen::Vector3d d(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                              std::sin(elevation));
      double range = 1e9;
      for (int axis = 0; axis < 3; ++axis) {
        if (std::abs(d[axis]) < 1e-9) continue;
        const double wall = d[axis] > 0.0 ? hi[axis] : lo[axis];
        range = std::min(range, (wall - origin[axis]) / d[axis]);
      }
      LidarPoint p;
      p.p = (range * d).cast<float>();
      p.intensity = 100.0f;
      p.time = time;
      p.ring = static_cast<std::uint16_t>(r);
      scan.points.push_back(p);
    }
  }
  return scan;
}

ImageFrame texturedImage(double t, int width = kImageWidth, int height = kImageHeight) {
  ImageFrame frame;
  frame.timestamp = t;
  frame.image = cv::Mat(height, width, CV_8UC1);
  cv::RNG rng(static_cast<std::uint64_t>(1000.0 * t) + 1);
  rng.fill(frame.image, cv::RNG::UNIFORM, 0, 256);
  return frame;
}

Calibration smallCalibration() {
  Calibration calibration;
  calibration.camera = PinholeCamera(kImageWidth, kImageHeight, 100.0, 100.0, 80.0, 60.0);
  Eigen::Matrix3d R_camera_lidar;  // camera z along the LiDAR's x, camera y down
  R_camera_lidar << 0, -1, 0, 0, 0, -1, 1, 0, 0;
  calibration.T_camera_lidar = makePose(R_camera_lidar, Eigen::Vector3d(0.0, -0.1, 0.05));
  return calibration;
}

// Scans at 10 Hz and images at 15 Hz in time order over `seconds`; an
// optional item is broken: next() throws for it.
class FakeSource : public SensorSource {
 public:
  FakeSource(double seconds, bool with_camera, bool with_lidar) : camera_(with_camera), lidar_(with_lidar) {
    const int scans = with_lidar ? static_cast<int>(std::lround(seconds * 10.0)) : 0;
    const int images = with_camera ? static_cast<int>(std::lround(seconds * 15.0)) : 0;
    int s = 0, i = 0;
    while (s < scans || i < images) {
      const double ts = s / 10.0, ti = i / 15.0 + 0.01;
      if (s < scans && (i >= images || ts <= ti)) {
        items_.push_back(boxRoomScan(ts));
        ++s;
      } else {
        items_.push_back(texturedImage(ti));
        ++i;
      }
    }
  }

  std::optional<SensorData> next() override {
    if (throw_at_ && served_ == *throw_at_) throw Error("fake source", "broken item " + std::to_string(served_));
    if (served_ >= items_.size()) return std::nullopt;
    return items_[served_++];
  }
  Calibration calibration() const override { return smallCalibration(); }
  bool hasCamera() const override { return camera_; }
  bool hasLidar() const override { return lidar_; }

  void throwAt(std::size_t item) { throw_at_ = item; }
  // Replaces the `n`-th image with one of half the camera's size.
  void shrinkImage(std::size_t n) {
    std::size_t seen = 0;
    for (SensorData& item : items_)
      if (auto* image = std::get_if<ImageFrame>(&item); image && seen++ == n)
        *image = texturedImage(image->timestamp, kImageWidth / 2, kImageHeight / 2);
  }
  std::size_t size() const { return items_.size(); }

 private:
  bool camera_, lidar_;
  std::vector<SensorData> items_;
  std::size_t served_ = 0;
  std::optional<std::size_t> throw_at_;
};

struct Outcome {
  bool lvslam_error = false;
  bool other_error = false;
  std::string message;
  std::optional<PipelineRecords> records;
};

// Runs the pipeline on another thread; a hang (a thread waiting for an
// answer that never comes) ends the whole test program with a message, as
// no test could continue after it. The limit is far above any normal run.
Outcome runGuarded(SensorSource& source, const SystemConfig& config) {
  auto future = std::async(std::launch::async, [&] {
    Outcome o;
    try {
      o.records = runPipeline(source, config, {});
    } catch (const lvslam::Error& e) {
      o.lvslam_error = true;
      o.message = e.what();
    } catch (const std::exception& e) {
      o.other_error = true;
      o.message = e.what();
    }
    return o;
  });
  if (future.wait_for(std::chrono::seconds(120)) != std::future_status::ready) {
    std::fprintf(stderr, "runPipeline did not return: deadlock\n");
    std::_Exit(3);
  }
  return future.get();
}

SystemConfig configFor(RunMode mode, bool deterministic) {
  SystemConfig c;
  c.mode = mode;
  c.deterministic = deterministic;
  return c;
}

class PipelineModes : public ::testing::TestWithParam<bool> {};  // param: deterministic

TEST_P(PipelineModes, CompleteSourceGivesOneRecordPerFrameAndScan) {
  // The control for the failure tests: the same data without a fault runs through.
  FakeSource source(1.0, true, true);
  const Outcome o = runGuarded(source, configFor(RunMode::kFused, GetParam()));
  ASSERT_TRUE(o.records) << o.message;
  EXPECT_EQ(o.records->images, 15u);
  EXPECT_EQ(o.records->visual.size(), 15u);
  EXPECT_EQ(o.records->lidar.size(), 15u);
  EXPECT_EQ(o.records->scans.size(), 10u);
  EXPECT_DOUBLE_EQ(o.records->first_time, 0.0);
  EXPECT_DOUBLE_EQ(o.records->last_time, 14.0 / 15.0 + 0.01);
  // The box room registers: every camera frame after the first scan has a LiDAR pose.
  for (const LidarFrameRecord& l : o.records->lidar) EXPECT_TRUE(l.T_odom_lidar.has_value()) << l.t;
}

// A source that cannot be read further (a cut last scan or image) ends the
// run there: the records hold every item read before it, each camera frame
// with its online output, and say why the run stopped.
void expectStoppedAt(const Outcome& o, std::size_t at) {
  ASSERT_TRUE(o.records) << at << ": " << o.message;
  ASSERT_TRUE(o.records->input_fault) << at;
  EXPECT_STREQ(o.records->input_fault->what(), ("fake source: broken item " + std::to_string(at)).c_str());
  EXPECT_EQ(o.records->images + o.records->scans_read, at);
  EXPECT_EQ(o.records->online.size(), o.records->images) << at;
}

TEST_P(PipelineModes, SourceErrorInLidarModeStopsTheRunThere) {
  FakeSource source(1.0, true, true);
  source.throwAt(7);
  expectStoppedAt(runGuarded(source, configFor(RunMode::kLidar, GetParam())), 7);
}

TEST_P(PipelineModes, SourceErrorInFusedModeStopsTheRunThere) {
  for (const std::size_t at : {0u, 1u, 6u, 13u, 24u}) {  // first item, first image, mid-run, last item
    FakeSource source(1.0, true, true);
    ASSERT_EQ(source.size(), 25u);
    source.throwAt(at);
    expectStoppedAt(runGuarded(source, configFor(RunMode::kFused, GetParam())), at);
  }
}

TEST_P(PipelineModes, SourceErrorInVisualModeStopsTheRunThere) {
  FakeSource source(1.0, true, false);
  source.throwAt(5);
  expectStoppedAt(runGuarded(source, configFor(RunMode::kVisual, GetParam())), 5);
}

TEST_P(PipelineModes, WrongImageSizeInFusedModeFailsTheRun) {
  // In the threaded run the visual thread fails on this image while the
  // LiDAR thread waits for its segments: both must stop and the error surface.
  for (const std::size_t bad : {0u, 4u, 14u}) {
    FakeSource source(1.0, true, true);
    source.shrinkImage(bad);
    const Outcome o = runGuarded(source, configFor(RunMode::kFused, GetParam()));
    EXPECT_TRUE(o.lvslam_error) << bad << ": " << o.message;
    EXPECT_NE(o.message.find("80x60"), std::string::npos) << o.message;
  }
}

INSTANTIATE_TEST_SUITE_P(ThreadedAndDeterministic, PipelineModes, ::testing::Bool(),
                         [](const auto& info) { return info.param ? "deterministic" : "threaded"; });

TEST(Pipeline, ModeWithoutItsSensorIsAnError) {
  FakeSource lidar_only(0.3, false, true);
  const Outcome fused = runGuarded(lidar_only, configFor(RunMode::kFused, false));
  EXPECT_TRUE(fused.lvslam_error);
  EXPECT_NE(fused.message.find("mode fused"), std::string::npos) << fused.message;
  EXPECT_NE(fused.message.find("camera"), std::string::npos) << fused.message;
  FakeSource camera_only(0.3, true, false);
  const Outcome lidar = runGuarded(camera_only, configFor(RunMode::kLidar, false));
  EXPECT_TRUE(lidar.lvslam_error);
  EXPECT_NE(lidar.message.find("LiDAR"), std::string::npos) << lidar.message;
}

}  // namespace
}  // namespace lvslam::system
