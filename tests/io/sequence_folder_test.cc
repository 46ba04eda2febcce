#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "lvslam/core/error.h"
#include "lvslam/core/se3.h"
#include "lvslam/io/scan_file.h"
#include "lvslam/io/sequence_info.h"
#include "lvslam/io/sequence_reader.h"
#include "lvslam/io/sequence_writer.h"
#include "support/temp_dir.h"

namespace lvslam {
namespace {

using testing::errorMessageOf;
using testing::TempDir;

SequenceInfo makeInfo(std::vector<std::string> fields, TimeReference ref) {
  SequenceInfo info;
  info.name = "round trip";
  info.camera = CameraInfo{PinholeCamera(64, 48, 50.0, 51.0, 31.5, 23.5, RadTanDistortion{0.1, -0.02, 0.001, 0.002, 0.0}),
                           15.0};
  LidarInfo lidar;
  lidar.rings = 32;
  lidar.rate_hz = 10.0;
  lidar.point_fields = std::move(fields);
  lidar.time_reference = ref;
  info.lidar = lidar;
  info.T_camera_lidar = makePose(expSO3(Eigen::Vector3d(-1.2, 0.1, 1.3)), Eigen::Vector3d(0.05, -0.3, 0.1));
  info.groundtruth_frame = GroundTruthFrame::kCamera;
  return info;
}

LidarScan makeScan(double t, int n, float time_sign) {
  LidarScan scan;
  scan.timestamp = t;
  scan.has_intensity = scan.has_time = scan.has_ring = true;
  for (int i = 0; i < n; ++i) {
    LidarPoint p;
    p.p = {1.0f + i, -2.0f * i + 0.5f, 0.25f * i + 0.1f};
    p.intensity = 10.0f * i;
    p.time = time_sign * 0.001f * i;
    p.ring = static_cast<std::uint16_t>(i % 32);
    scan.points.push_back(p);
  }
  return scan;
}

TEST(SequenceFolder, WriteReadRoundTripMergesSensorsInTimeOrder) {
  TempDir dir;
  const SequenceInfo info = makeInfo({"x", "y", "z", "intensity", "time", "ring"}, TimeReference::kStart);
  {
    SequenceWriter writer(dir.file("seq"), info);
    cv::Mat img(48, 64, CV_8UC3, cv::Scalar(10, 20, 30));
    writer.writeScan(makeScan(100.0, 5, 1.0f));
    writer.writeImage(100.05, img);
    writer.writeImage(100.1, img);  // same time as the next scan: scan first
    writer.writeScan(makeScan(100.1, 7, 1.0f));
    writer.writeGroundTruth({{100.0, Eigen::Isometry3d::Identity()}, {100.1, info.T_camera_lidar}});
  }
  SequenceReader reader(dir.file("seq"));
  EXPECT_EQ(reader.info().name, "round trip");
  EXPECT_TRUE(reader.info().T_camera_lidar.isApprox(info.T_camera_lidar, 1e-12));
  const PinholeCamera& cam = reader.info().camera->camera;
  EXPECT_DOUBLE_EQ(cam.fy(), 51.0);
  EXPECT_DOUBLE_EQ(cam.distortion().p2, 0.002);
  EXPECT_EQ(*reader.info().groundtruth_frame, GroundTruthFrame::kCamera);

  std::vector<std::pair<double, bool>> order;  // (time, is_scan)
  while (auto data = reader.next()) {
    if (auto* scan = std::get_if<LidarScan>(&*data)) {
      order.emplace_back(scan->timestamp, true);
      const LidarScan expected = makeScan(scan->timestamp, scan->timestamp < 100.05 ? 5 : 7, 1.0f);
      ASSERT_EQ(scan->size(), expected.size());
      for (std::size_t i = 0; i < scan->size(); ++i) {
        EXPECT_EQ(scan->points[i].p, expected.points[i].p);
        EXPECT_EQ(scan->points[i].time, expected.points[i].time);
        EXPECT_EQ(scan->points[i].ring, expected.points[i].ring);
        EXPECT_EQ(scan->points[i].intensity, expected.points[i].intensity);
      }
    } else {
      const auto& frame = std::get<ImageFrame>(*data);
      order.emplace_back(frame.timestamp, false);
      EXPECT_EQ(frame.image.channels(), 3);
      EXPECT_EQ(frame.image.at<cv::Vec3b>(5, 5), cv::Vec3b(10, 20, 30));
    }
  }
  const std::vector<std::pair<double, bool>> expected{{100.0, true}, {100.05, false}, {100.1, true}, {100.1, false}};
  EXPECT_EQ(order, expected);
  EXPECT_EQ(reader.groundTruth().size(), 2u);
}

// sequence.yaml goes through yaml-cpp's emitter: any name reads back as
// written (quotes, backslashes, a YAML comment sign, unicode, a newline) and
// every double exactly (the extrinsic to rounding: the reader re-orthonormalises it).
TEST(SequenceFolder, SequenceYamlReadsBackExactlyWhateverTheName) {
  for (const std::string& name : {std::string("quote\"name"), std::string("seq\\1"), std::string("a: b # c"),
                                 std::string("caf\u00e9 \u2192 \u00fcber"), std::string("two\nlines"),
                                 std::string("")}) {
    TempDir dir;
    SequenceInfo info = makeInfo({"x", "y", "z", "intensity", "time", "ring"}, TimeReference::kEnd);
    info.name = name;
    info.camera->rate_hz = 1.0 / 3.0;
    info.groundtruth_frame = GroundTruthFrame::kLidar;
    const std::string path = dir.file("sequence.yaml");
    writeSequenceInfo(path, info);
    const SequenceInfo back = readSequenceInfo(path);
    EXPECT_EQ(back.name, name);
    EXPECT_EQ(back.camera->rate_hz, 1.0 / 3.0);
    EXPECT_EQ(back.camera->camera.cx(), 31.5);
    EXPECT_EQ(back.camera->camera.distortion().k2, -0.02);
    EXPECT_EQ(back.lidar->point_fields, info.lidar->point_fields);
    EXPECT_EQ(back.lidar->time_reference, TimeReference::kEnd);
    EXPECT_EQ(*back.groundtruth_frame, GroundTruthFrame::kLidar);
    EXPECT_TRUE(back.T_camera_lidar.isApprox(info.T_camera_lidar, 1e-14)) << name;  // the reader re-orthonormalises R
  }
}

TEST(SequenceFolder, KittiStyleFourFieldScansWithEndReference) {
  TempDir dir;
  SequenceInfo info = makeInfo({"x", "y", "z", "intensity"}, TimeReference::kEnd);
  info.camera.reset();
  info.groundtruth_frame.reset();
  {
    SequenceWriter writer(dir.file("kitti"), info);
    writer.writeScan(makeScan(5.0, 4, -1.0f));
  }
  EXPECT_EQ(std::filesystem::file_size(dir.file("kitti/lidar/000000.bin")), 4u * 4u * sizeof(float));
  SequenceReader reader(dir.file("kitti"));
  EXPECT_EQ(reader.info().lidar->time_reference, TimeReference::kEnd);
  const LidarScan scan = reader.loadScan(0);
  EXPECT_FALSE(scan.has_time);
  EXPECT_FALSE(scan.has_ring);
  ASSERT_EQ(scan.size(), 4u);
  EXPECT_EQ(scan.points[3].p, Eigen::Vector3f(4.0f, -5.5f, 0.85f));
  EXPECT_EQ(scan.points[3].intensity, 30.0f);
}

TEST(SequenceFolder, EndReferenceKeepsNegativePointTimes) {
  TempDir dir;
  SequenceInfo info = makeInfo({"x", "y", "z", "time"}, TimeReference::kEnd);
  info.camera.reset();
  {
    SequenceWriter writer(dir.file("s"), info);
    writer.writeScan(makeScan(7.0, 3, -1.0f));
  }
  const LidarScan scan = SequenceReader(dir.file("s")).loadScan(0);
  ASSERT_EQ(scan.size(), 3u);
  EXPECT_FLOAT_EQ(scan.points[2].time, -0.002f);
  EXPECT_NEAR(scan.pointTime(2), 6.998, 1e-9);
}

TEST(SequenceFolder, ArbitraryFieldOrderAndUnknownFieldsAreRead) {
  TempDir dir;
  // A record of [ring, pad, z, time, y, x] floats.
  const std::vector<float> rec{3.0f, 99.0f, 0.5f, 0.02f, -1.5f, 2.0f};
  std::ofstream(dir.file("scan.bin"), std::ios::binary)
      .write(reinterpret_cast<const char*>(rec.data()), rec.size() * sizeof(float));
  LidarScan scan;
  readScanFile(dir.file("scan.bin"), ScanLayout::fromFields({"ring", "pad", "z", "time", "y", "x"}), scan);
  ASSERT_EQ(scan.size(), 1u);
  EXPECT_EQ(scan.points[0].p, Eigen::Vector3f(2.0f, -1.5f, 0.5f));
  EXPECT_EQ(scan.points[0].ring, 3);
  EXPECT_FLOAT_EQ(scan.points[0].time, 0.02f);
}

TEST(SequenceFolder, NanAndOriginPointsAreDropped) {
  TempDir dir;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> recs{1, 2, 3, nan, 1, 1, 0, 0, 0, 4, 5, 6, 1, std::numeric_limits<float>::infinity(), 1};
  std::ofstream(dir.file("s.bin"), std::ios::binary)
      .write(reinterpret_cast<const char*>(recs.data()), recs.size() * sizeof(float));
  LidarScan scan;
  const ScanReadStats stats = readScanFile(dir.file("s.bin"), ScanLayout::fromFields({"x", "y", "z"}), scan);
  EXPECT_EQ(stats.records, 5u);
  EXPECT_EQ(stats.dropped, 3u);
  ASSERT_EQ(scan.size(), 2u);
  EXPECT_EQ(scan.points[1].p, Eigen::Vector3f(4, 5, 6));
}

TEST(SequenceFolder, ScanSizeNotAMultipleOfTheRecordIsAnErrorNamingTheFile) {
  TempDir dir;
  dir.write("bad.bin", std::string(4 * 6 * 2 + 5, '\0'));
  LidarScan scan;
  const std::string msg = errorMessageOf(
      [&] { readScanFile(dir.file("bad.bin"), ScanLayout::fromFields({"x", "y", "z", "intensity", "time", "ring"}), scan); });
  EXPECT_NE(msg.find("bad.bin"), std::string::npos) << msg;
  EXPECT_NE(msg.find("multiple of the record size 24"), std::string::npos) << msg;
}

// A valid LiDAR-only folder, to be broken by each bad-input test.
void writeValidFolder(const TempDir& dir, const std::string& yaml_extra = "") {
  dir.write("seq/sequence.yaml",
            "format: lvslam-sequence/1\nlidar:\n  point_fields: [x, y, z]\n  time_reference: start\n" + yaml_extra);
  dir.write("seq/lidar/a.bin", std::string(12, '\0'));
  dir.write("seq/lidar/b.bin", std::string(12, '\0'));
  dir.write("seq/lidar/times.txt", "# t file\n1.0 a.bin\n\n1.1 b.bin\n");
}

TEST(SequenceFolderBadInput, MissingFolderAndMissingYaml) {
  TempDir dir;
  EXPECT_NE(errorMessageOf([&] { SequenceReader r(dir.file("nope")); }).find("nope"), std::string::npos);
  std::filesystem::create_directories(dir.file("empty"));
  EXPECT_NE(errorMessageOf([&] { SequenceReader r(dir.file("empty")); }).find("sequence.yaml"), std::string::npos);
}

TEST(SequenceFolderBadInput, WrongFormatStringNamesTheKey) {
  TempDir dir;
  writeValidFolder(dir);
  dir.write("seq/sequence.yaml", "format: lvslam-sequence/2\nlidar:\n  point_fields: [x, y, z]\n");
  const std::string msg = errorMessageOf([&] { SequenceReader r(dir.file("seq")); });
  EXPECT_NE(msg.find("'format'"), std::string::npos) << msg;
}

TEST(SequenceFolderBadInput, MalformedYaml) {
  TempDir dir;
  writeValidFolder(dir);
  dir.write("seq/sequence.yaml", "format: lvslam-sequence/1\nlidar: [unclosed\n");
  const std::string msg = errorMessageOf([&] { SequenceReader r(dir.file("seq")); });
  EXPECT_NE(msg.find("sequence.yaml"), std::string::npos) << msg;
  EXPECT_NE(msg.find("malformed YAML"), std::string::npos) << msg;
}

TEST(SequenceFolderBadInput, ExtrinsicThatIsNotARotationNamesTheKey) {
  TempDir dir;
  writeValidFolder(dir,
                   "extrinsics:\n  T_camera_lidar: [1, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]\n");
  const std::string msg = errorMessageOf([&] { SequenceReader r(dir.file("seq")); });
  EXPECT_NE(msg.find("extrinsics.T_camera_lidar"), std::string::npos) << msg;
  EXPECT_NE(msg.find("not a rotation"), std::string::npos) << msg;
}

TEST(SequenceFolderBadInput, ExtrinsicWithTwelveNumbers) {
  TempDir dir;
  writeValidFolder(dir, "extrinsics:\n  T_camera_lidar: [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0]\n");
  const std::string msg = errorMessageOf([&] { SequenceReader r(dir.file("seq")); });
  EXPECT_NE(msg.find("expected 16 numbers"), std::string::npos) << msg;
}

TEST(SequenceFolderBadInput, CameraWithoutIntrinsicsNamesTheKey) {
  TempDir dir;
  writeValidFolder(dir, "camera:\n  width: 640\n  height: 480\n");
  const std::string msg = errorMessageOf([&] { SequenceReader r(dir.file("seq")); });
  EXPECT_NE(msg.find("camera.intrinsics"), std::string::npos) << msg;
}

TEST(SequenceFolderBadInput, UnsortedAndDuplicateTimesNameFileAndLine) {
  TempDir dir;
  writeValidFolder(dir);
  dir.write("seq/lidar/times.txt", "1.1 a.bin\n1.0 b.bin\n");
  std::string msg = errorMessageOf([&] { SequenceReader r(dir.file("seq")); });
  EXPECT_NE(msg.find("times.txt:2"), std::string::npos) << msg;
  dir.write("seq/lidar/times.txt", "1.0 a.bin\n1.0 b.bin\n");
  msg = errorMessageOf([&] { SequenceReader r(dir.file("seq")); });
  EXPECT_NE(msg.find("times.txt:2"), std::string::npos) << msg;
}

TEST(SequenceFolderBadInput, MissingScanFileAndMalformedTimeNameTheLine) {
  TempDir dir;
  writeValidFolder(dir);
  dir.write("seq/lidar/times.txt", "1.0 a.bin\n1.1 missing.bin\n");
  std::string msg = errorMessageOf([&] { SequenceReader r(dir.file("seq")); });
  EXPECT_NE(msg.find("times.txt:2"), std::string::npos) << msg;
  EXPECT_NE(msg.find("missing.bin"), std::string::npos) << msg;
  dir.write("seq/lidar/times.txt", "1.0 a.bin\n1.1x b.bin\n");
  msg = errorMessageOf([&] { SequenceReader r(dir.file("seq")); });
  EXPECT_NE(msg.find("times.txt:2"), std::string::npos) << msg;
}

TEST(SequenceFolderBadInput, FileNameTooLongNamesTheLine) {
  TempDir dir;
  writeValidFolder(dir);
  dir.write("seq/lidar/times.txt", "1.0 a.bin\n1.1 " + std::string(300, 'b') + ".bin\n");
  const std::string msg = errorMessageOf([&] { SequenceReader r(dir.file("seq")); });
  EXPECT_NE(msg.find("times.txt:2: cannot access"), std::string::npos) << msg;
  EXPECT_NE(msg.find("too long"), std::string::npos) << msg;
}

TEST(SequenceFolderBadInput, SymlinkLoopAsTheFolderIsAnError) {
  TempDir dir;
  std::filesystem::create_symlink(dir.file("seq"), dir.file("seq"));
  const std::string msg = errorMessageOf([&] { SequenceReader r(dir.file("seq")); });
  EXPECT_NE(msg.find("seq: cannot access"), std::string::npos) << msg;
}

TEST(SequenceFolder, ADeclaredSensorWithoutDataCountsAsAbsent) {
  TempDir dir;
  writeValidFolder(dir, "camera:\n  width: 64\n  height: 48\n  intrinsics: [50, 50, 32, 24]\n"
                        "extrinsics:\n  T_camera_lidar: [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]\n");
  dir.write("seq/camera/times.txt", "# no images\n");
  const SequenceReader reader(dir.file("seq"));
  EXPECT_TRUE(reader.info().camera.has_value());
  EXPECT_FALSE(reader.hasCamera());
  EXPECT_TRUE(reader.hasLidar());
}

TEST(SequenceFolderBadInput, AFolderMarkedIncompleteIsRefused) {
  TempDir dir;
  writeValidFolder(dir);
  dir.write("seq/INCOMPLETE", "");
  const std::string msg = errorMessageOf([&] { SequenceReader r(dir.file("seq")); });
  EXPECT_NE(msg.find("seq/INCOMPLETE: the folder is incomplete"), std::string::npos) << msg;
}

TEST(SequenceFolderBadInput, GroundTruthWithoutFrameKey) {
  TempDir dir;
  writeValidFolder(dir);
  dir.write("seq/groundtruth.txt", "1.0 0 0 0 0 0 0 1\n");
  const std::string msg = errorMessageOf([&] { SequenceReader r(dir.file("seq")); });
  EXPECT_NE(msg.find("groundtruth.frame"), std::string::npos) << msg;
}

TEST(SequenceFolderBadInput, ImageOfTheWrongSizeNamesTheFile) {
  TempDir dir;
  dir.write("seq/sequence.yaml",
            "format: lvslam-sequence/1\ncamera:\n  width: 64\n  height: 48\n  intrinsics: [50, 50, 32, 24]\n");
  std::filesystem::create_directories(dir.file("seq/camera"));
  cv::imwrite(dir.file("seq/camera/0.png"), cv::Mat(10, 10, CV_8UC1, cv::Scalar(0)));
  dir.write("seq/camera/times.txt", "0.5 0.png\n");
  SequenceReader reader(dir.file("seq"));
  const std::string msg = errorMessageOf([&] { reader.next(); });
  EXPECT_NE(msg.find("0.png"), std::string::npos) << msg;
  EXPECT_NE(msg.find("10x10"), std::string::npos) << msg;
}

TEST(SequenceFolder, TimeJumpsAreFound) {
  std::vector<TimedFile> files;
  for (double t : {0.0, 0.1, 0.2, 0.3, 2.3, 2.4}) files.push_back({t, ""});
  EXPECT_EQ(findTimeJumps(files), std::vector<std::size_t>{4});
}

}  // namespace
}  // namespace lvslam
