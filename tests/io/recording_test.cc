#include "lvslam/io/recording.h"

#include <filesystem>

#include <gtest/gtest.h>

#include "lvslam/io/sequence_writer.h"
#include "support/temp_dir.h"

namespace lvslam {
namespace {

using testing::errorMessageOf;
using testing::TempDir;

TEST(Recording, SequenceFolderBringsItsGroundTruthAndFrame) {
  TempDir dir;
  SequenceInfo info;
  info.name = "tiny";
  info.lidar = LidarInfo{};
  info.lidar->point_fields = {"x", "y", "z"};
  info.groundtruth_frame = GroundTruthFrame::kLidar;
  {
    SequenceWriter writer(dir.file("seq"), info);
    LidarScan scan;
    scan.timestamp = 1.0;
    scan.points.resize(3);
    for (int i = 0; i < 3; ++i) scan.points[i].p = Eigen::Vector3f(1.0f + i, 0.0f, 0.0f);
    writer.writeScan(scan);
    writer.writeGroundTruth({{1.0, Eigen::Isometry3d::Identity()}, {2.0, Eigen::Isometry3d::Identity()}});
  }
  RecordingRequest request;
  request.sequence_dir = dir.file("seq");
  Recording rec = openRecording(request);
  EXPECT_EQ(rec.name, "tiny");
  ASSERT_TRUE(rec.ground_truth.has_value());
  EXPECT_EQ(rec.ground_truth->size(), 2u);
  EXPECT_EQ(rec.ground_truth_frame, GroundTruthFrame::kLidar);
  const auto first = rec.source->next();
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(std::get<LidarScan>(*first).size(), 3u);
  EXPECT_FALSE(rec.source->next().has_value());
}

TEST(Recording, NeedsExactlyOneInputAndAPresetForBags) {
  RecordingRequest none;
  EXPECT_NE(errorMessageOf([&] { openRecording(none); }).find("--sequence/--bag"), std::string::npos);
  RecordingRequest both;
  both.sequence_dir = "a";
  both.bag_files = {"b.bag"};
  EXPECT_NE(errorMessageOf([&] { openRecording(both); }).find("--sequence/--bag"), std::string::npos);
#ifdef LVSLAM_HAS_ROSBAG
  RecordingRequest no_preset;
  no_preset.bag_files = {"b.bag"};
  EXPECT_NE(errorMessageOf([&] { openRecording(no_preset); }).find("--preset"), std::string::npos);
#endif
}

#ifdef LVSLAM_HAS_ROSBAG
TEST(Recording, RealBagStreamsItsScansThroughAPreset) {
  const std::string bag = std::string(LVSLAM_SHARED_DATA_DIR) + "/ros1/embag-test.bag";
  if (!std::filesystem::exists(bag)) GTEST_SKIP() << "shared test data not found: " << bag;
  TempDir dir;
  dir.write("p.yaml", "format: lvslam-preset/1\ntopics:\n  lidar: /luminar_pointcloud\n");
  RecordingRequest request;
  request.bag_files = {bag};
  request.preset = dir.file("p.yaml");
  Recording rec = openRecording(request);
  EXPECT_TRUE(rec.source->hasLidar());
  EXPECT_FALSE(rec.source->hasCamera());
  int scans = 0;
  while (auto data = rec.source->next()) scans += std::holds_alternative<LidarScan>(*data) ? 1 : 0;
  EXPECT_EQ(scans, 5);  // /luminar_pointcloud has 5 messages (shared/data/README.md)
}
#endif

}  // namespace
}  // namespace lvslam
