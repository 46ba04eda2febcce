// `lvslam convert to-bag`: a sequence written as a bag and read back through
// its preset (the path lvslam_node and `lvslam run --bag` take) gives the
// same images and scans, in the same order, with the same calibration.
#include "lvslam/io/sequence_to_bag.h"

#include <filesystem>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "lvslam/core/error.h"
#include "lvslam/io/recording.h"
#include "lvslam/io/rosbag_reader.h"
#include "lvslam/io/sensor_preset.h"
#include "lvslam/io/sequence_writer.h"
#include "support/temp_dir.h"

namespace lvslam {
namespace {

using testing::TempDir;

LidarScan sweep(double t) {
  LidarScan scan;
  scan.timestamp = t;
  scan.has_intensity = scan.has_time = scan.has_ring = true;
  for (int i = 0; i < 5; ++i) {
    LidarPoint p;
    p.p = Eigen::Vector3f(1.0f + i, -2.0f * i, 0.5f);
    p.intensity = 10.0f * i;
    p.time = 0.02f * i;  // a sweep of 0.08 s, stamped at its start
    p.ring = static_cast<std::uint16_t>(i);
    scan.points.push_back(p);
  }
  return scan;
}

std::string writeSequence(const TempDir& dir) {
  SequenceInfo info;
  info.name = "roundtrip";
  info.camera = CameraInfo{PinholeCamera(8, 6, 5.0, 5.0, 4.0, 3.0), 15.0};
  info.lidar = LidarInfo{};
  info.T_camera_lidar.translation() = Eigen::Vector3d(0.1, -0.2, 0.3);
  SequenceWriter writer(dir.file("seq"), info);
  cv::Mat image(6, 8, CV_8UC1);
  for (int k = 0; k < 3; ++k) {
    writer.writeScan(sweep(1.0 + 0.1 * k));
    image.setTo(cv::Scalar(40 * k));
    writer.writeImage(1.05 + 0.1 * k, image);
  }
  return dir.file("seq");
}

void expectRoundTrip(BagImageFormat format) {
  TempDir dir;
  SequenceToBagOptions options;
  options.sequence_dir = writeSequence(dir);
  options.bag_path = dir.file("seq.bag");
  options.image_format = format;
  const SequenceToBagStats stats = writeSequenceBag(options);
  EXPECT_EQ(stats.images, 3u);
  EXPECT_EQ(stats.scans, 3u);
  EXPECT_EQ(stats.preset_path, dir.file("seq.preset.yaml"));

  const SensorPreset preset = loadSensorPreset(stats.preset_path);
  EXPECT_EQ(preset.lidar_topic, options.lidar_topic);
  EXPECT_EQ(preset.camera_topic, cameraTopicOf(options));
  ASSERT_TRUE(preset.camera.has_value());
  EXPECT_EQ(preset.camera->camera.width(), 8);
  EXPECT_TRUE(preset.T_camera_lidar.isApprox(SequenceInfo{}.T_camera_lidar * Eigen::Translation3d(0.1, -0.2, 0.3)));

  RecordingRequest request;
  request.sequence_dir = options.sequence_dir;
  Recording folder = openRecording(request);
  RecordingRequest from_bag;
  from_bag.bag_files = {options.bag_path};
  from_bag.preset = stats.preset_path;
  Recording bag = openRecording(from_bag);
  std::size_t items = 0;
  while (auto expected = folder.source->next()) {
    const auto got = bag.source->next();
    ASSERT_TRUE(got.has_value()) << "item " << items;
    ASSERT_EQ(expected->index(), got->index()) << "item " << items;
    EXPECT_NEAR(stampOf(*expected), stampOf(*got), 1e-9);
    if (const auto* scan = std::get_if<LidarScan>(&*expected)) {
      const auto& back = std::get<LidarScan>(*got);
      ASSERT_EQ(back.size(), scan->size());
      for (std::size_t i = 0; i < scan->size(); ++i) {
        EXPECT_EQ(back.points[i].p, scan->points[i].p);
        EXPECT_EQ(back.points[i].time, scan->points[i].time);
        EXPECT_EQ(back.points[i].ring, scan->points[i].ring);
        EXPECT_EQ(back.points[i].intensity, scan->points[i].intensity);
      }
    } else {
      const cv::Mat diff = std::get<ImageFrame>(*expected).image != std::get<ImageFrame>(*got).image;
      EXPECT_EQ(cv::countNonZero(diff), 0);
    }
    ++items;
  }
  EXPECT_EQ(items, 6u);
  EXPECT_FALSE(bag.source->next().has_value());
}

TEST(SequenceToBag, ReadsBackThroughItsPresetAsTheSequence) { expectRoundTrip(BagImageFormat::kRaw); }

TEST(SequenceToBag, PngCompressedImagesReadBackExactly) {
  SequenceToBagOptions options;
  options.image_format = BagImageFormat::kPng;
  EXPECT_EQ(cameraTopicOf(options), "/camera/image_raw/compressed");  // image_transport's name: the node reads it as such
  expectRoundTrip(BagImageFormat::kPng);
}

TEST(SequenceToBag, RecordsEachSweepWhenItEnds) {
  TempDir dir;
  SequenceToBagOptions options;
  options.sequence_dir = writeSequence(dir);
  options.bag_path = dir.file("seq.bag");
  writeSequenceBag(options);
  RosbagReader reader(options.bag_path);
  reader.select({options.lidar_topic});
  const auto first = reader.next();
  ASSERT_TRUE(first.has_value());
  EXPECT_NEAR(first->record_time, 1.0 + 0.08, 1e-6);  // the last point's time, as a driver publishes
}

TEST(SequenceToBag, AFailedConversionLeavesNoBag) {
  TempDir dir;
  SequenceToBagOptions options;
  options.sequence_dir = dir.file("missing");
  options.bag_path = dir.file("out.bag");
  EXPECT_THROW(writeSequenceBag(options), Error);
  EXPECT_FALSE(std::filesystem::exists(options.bag_path));
  EXPECT_FALSE(std::filesystem::exists(options.bag_path + ".partial"));
}

// A sequence may carry keys the format ignores; its preset must still load
// (a preset refuses unknown keys), with the sequence's calibration.
TEST(SequenceToBag, KeysASequenceMayCarryStayOutOfItsPreset) {
  TempDir dir;
  SequenceToBagOptions options;
  options.sequence_dir = writeSequence(dir);
  options.bag_path = dir.file("seq.bag");
  const std::string yaml = options.sequence_dir + "/sequence.yaml";
  std::string text;
  {
    std::ifstream in(yaml);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::size_t camera = text.find("camera:\n");
  ASSERT_NE(camera, std::string::npos);
  text.insert(camera + 8, "  exposure_ms: 12\n");
  text += "recorded_by: a test\n";
  std::ofstream(yaml) << text;
  ASSERT_EQ(readSequenceInfo(yaml).camera->camera.width(), 8);  // the sequence ignores them
  const SequenceToBagStats stats = writeSequenceBag(options);
  const SensorPreset preset = loadSensorPreset(stats.preset_path);
  ASSERT_TRUE(preset.camera.has_value());
  EXPECT_EQ(preset.camera->camera.width(), 8);
}

}  // namespace
}  // namespace lvslam
