#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <yaml-cpp/yaml.h>

#include "lvslam/core/se3.h"
#include "lvslam/io/sequence_reader.h"
#include "lvslam/io/tum.h"
#include "lvslam/sim/simulate_sequence.h"
#include "support/temp_dir.h"

namespace lvslam::sim {
namespace {

namespace fs = std::filesystem;

std::string bytesOf(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Every file of the folder, by relative path, with its bytes.
std::map<std::string, std::string> folderContents(const fs::path& root) {
  std::map<std::string, std::string> contents;
  for (const auto& entry : fs::recursive_directory_iterator(root))
    if (entry.is_regular_file()) contents[fs::relative(entry.path(), root).string()] = bytesOf(entry.path());
  return contents;
}

SimOptions shortRoom(std::uint64_t seed) {
  SimOptions options;
  options.duration = 0.3;
  options.seed = seed;
  return options;
}

TEST(SimulatedFolder, SameSeedSameBytesOtherSeedOtherBytes) {
  testing::TempDir a, b, c;
  simulateSequence(shortRoom(5), a.path().string());
  simulateSequence(shortRoom(5), b.path().string());
  simulateSequence(shortRoom(6), c.path().string());
  const auto ca = folderContents(a.path()), cb = folderContents(b.path()), cc = folderContents(c.path());
  ASSERT_GT(ca.size(), 8u);
  EXPECT_TRUE(ca == cb);
  ASSERT_EQ(ca.size(), cc.size());
  for (const auto& [name, bytes] : ca) {
    if (name.starts_with("camera/0") || name.starts_with("lidar/0")) {
      EXPECT_NE(bytes, cc.at(name)) << name;
    }
  }
}

TEST(SimulatedFolder, FollowsTheSequenceFormatWithUnsynchronisedUnixTimes) {
  testing::TempDir dir;
  const SimulationSummary summary = simulateSequence(shortRoom(1), dir.path().string());
  const SequenceReader reader(dir.path().string());
  ASSERT_EQ(reader.cameraFiles().size(), static_cast<std::size_t>(summary.images));
  ASSERT_EQ(reader.lidarFiles().size(), static_cast<std::size_t>(summary.scans));
  EXPECT_EQ(summary.images, 5);  // 15 Hz over 0.3 s
  EXPECT_EQ(summary.scans, 2);   // whole 0.1 s sweeps only
  const double camera_start = reader.cameraFiles()[0].t, lidar_start = reader.lidarFiles()[0].t;
  EXPECT_GT(camera_start, 1.7e9);
  EXPECT_GT(std::abs(camera_start - lidar_start), 1e-3);
  EXPECT_NEAR(reader.cameraFiles()[1].t - camera_start, 1.0 / 15.0, 1e-6);
  EXPECT_NEAR(reader.lidarFiles()[1].t - lidar_start, 0.1, 1e-6);
  EXPECT_EQ(reader.info().groundtruth_frame, GroundTruthFrame::kCamera);
  // Ground truth at 200 Hz and at every image and scan time is the renderer's
  // own camera pose: 61 grid poses over 0.3 s plus 5 image and 2 scan times
  // (none on the grid: the streams start 12.7 and 51.9 ms in).
  const Trajectory gt = readTum(dir.file("groundtruth.txt"));
  ASSERT_EQ(gt.size(), 61u + 5u + 2u);
  EXPECT_EQ(summary.groundtruth_poses, 68);
  for (std::size_t i = 1; i < gt.size(); ++i) EXPECT_GT(gt[i].t, gt[i - 1].t);
  // Each sensor time has a ground-truth pose at exactly its time stamp (as
  // the TUM files write both), so evaluation compares at the image's time.
  const auto hasPoseAt = [&](double t) {
    return std::any_of(gt.begin(), gt.end(), [&](const StampedPose& p) { return std::abs(p.t - t) < 1e-9; });
  };
  for (const auto& image : reader.cameraFiles()) EXPECT_TRUE(hasPoseAt(image.t)) << image.t;
  for (const auto& scan : reader.lidarFiles()) EXPECT_TRUE(hasPoseAt(scan.t)) << scan.t;
  const Scenario scenario = makeScenario(shortRoom(1));
  for (const StampedPose& pose : gt) {
    const Eigen::Isometry3d truth = scenario.T_world_camera(pose.t - 1700000000.0);
    EXPECT_LT((pose.T_world_frame.translation() - truth.translation()).norm(), 1e-6);
    EXPECT_LT(rotationAngle(pose.T_world_frame.inverse() * truth), 1e-6);
  }
  // The rig: camera z (forward) is LiDAR x, camera x is -LiDAR y, camera y is -LiDAR z.
  Eigen::Matrix3d R_lidar_camera;
  R_lidar_camera << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  EXPECT_LT((reader.info().T_camera_lidar.linear().transpose() - R_lidar_camera).norm(), 1e-12);
}

TEST(SimulatedFolder, BlackoutImagesAreAllZero) {
  testing::TempDir dir;
  SimOptions options = shortRoom(1);
  options.camera_blackout = TimeInterval{0.05, 0.15};
  simulateSequence(options, dir.path().string());
  const SequenceReader reader(dir.path().string());
  int black = 0;
  for (std::size_t i = 0; i < reader.cameraFiles().size(); ++i) {
    const ImageFrame frame = reader.loadImage(i);
    const double t = frame.timestamp - options.start_time;
    const bool inside = t >= 0.05 && t <= 0.15;
    if (inside) ++black;
    EXPECT_EQ(cv::countNonZero(frame.image) == 0, inside) << "t = " << t;
  }
  EXPECT_EQ(black, 2);
}

TEST(SimulatedFolder, ALidarDropOutWritesNoSweepStartingInIt) {
  testing::TempDir dir;
  SimOptions options = shortRoom(1);
  options.duration = 0.6;
  options.lidar_dropout = TimeInterval{0.12, 0.32};
  const SimulationSummary summary = simulateSequence(options, dir.path().string());
  const SequenceReader reader(dir.path().string());
  ASSERT_EQ(reader.lidarFiles().size(), static_cast<std::size_t>(summary.scans));
  EXPECT_EQ(summary.scans, 3);  // sweeps start at 0.05 s and every 0.1 s after; those at 0.15 and 0.25 s are missing
  for (const auto& file : reader.lidarFiles()) {
    const double t = file.t - options.start_time;
    EXPECT_FALSE(t >= 0.12 && t <= 0.32) << t;
  }
}

Eigen::Isometry3d matrixFrom(const YAML::Node& node) {
  Eigen::Matrix4d M;
  for (int i = 0; i < 16; ++i) M(i / 4, i % 4) = node[i].as<double>();
  Eigen::Isometry3d T;
  T.matrix() = M;
  return T;
}

TEST(SimulatedFolder, ExtrinsicErrorHasExactlyTheRequestedSize) {
  testing::TempDir dir;
  SimOptions options = shortRoom(3);
  options.extrinsic_error = ExtrinsicError{2.5, 0.08};
  simulateSequence(options, dir.path().string());
  const SequenceReader reader(dir.path().string());
  const YAML::Node truth_file = YAML::LoadFile(dir.file(kExtrinsicsTruthFile));
  const Eigen::Isometry3d truth = matrixFrom(truth_file["T_camera_lidar"]);
  const Eigen::Isometry3d written = reader.info().T_camera_lidar;
  EXPECT_NEAR(rotationAngle(makePose(Eigen::Matrix3d(written.linear() * truth.linear().transpose()),
                                     Eigen::Vector3d::Zero())) * 180.0 / M_PI,
              2.5, 1e-9);
  EXPECT_NEAR((written.translation() - truth.translation()).norm(), 0.08, 1e-12);
  EXPECT_DOUBLE_EQ(truth_file["perturbation"]["rotation_deg"].as<double>(), 2.5);
  // The truth file holds the rig's true extrinsics.
  const Scenario scenario = makeScenario(options);
  EXPECT_LT((truth.matrix() - scenario.rig.T_camera_lidar().matrix()).norm(), 1e-15);
}

}  // namespace
}  // namespace lvslam::sim
