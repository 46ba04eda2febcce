// `lvslam eval` compares in the ground truth's frame: with
// --sequence it takes groundtruth.frame and the extrinsic from the folder,
// and gives the figure `lvslam run` prints for the same trajectory.
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "apps/clean_sequence.h"
#include "apps/run_lvslam.h"
#include "lvslam/io/sequence_info.h"
#include "lvslam/io/tum.h"
#include "support/temp_dir.h"

namespace lvslam {
namespace {

using testing::lines;
using testing::RunResult;
using testing::runLvslam;
using testing::TempDir;

// The clean sequence with its ground truth moved into the LiDAR frame
// (T_world_lidar = T_world_camera * T_camera_lidar) and declared so.
void lidarFrameGroundTruth(const TempDir& dir) {
  testing::cleanSequence(dir);
  SequenceInfo info = readSequenceInfo(dir.file("seq/sequence.yaml"));
  Trajectory gt = readTum(dir.file("seq/groundtruth.txt"));
  for (StampedPose& pose : gt) pose.T_world_frame = pose.T_world_frame * info.T_camera_lidar;
  writeTum(dir.file("seq/groundtruth.txt"), gt);
  info.groundtruth_frame = GroundTruthFrame::kLidar;
  writeSequenceInfo(dir.file("seq/sequence.yaml"), info);
}

// The first "ATE (m): rmse ..." line of a summary.
std::string ateLine(const std::string& text) {
  std::smatch m;
  return std::regex_search(text, m, std::regex(R"(ATE \(m\): +rmse [0-9.]+)")) ? m.str() : "";
}

TEST(EvalFrames, SequenceGroundTruthInTheLidarFrameGivesRunsOwnFigure) {
  TempDir dir;
  lidarFrameGroundTruth(dir);
  const RunResult run = runLvslam(dir, "run --sequence seq --mode lidar --out out");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string expected = ateLine(run.out);
  ASSERT_FALSE(expected.empty()) << run.out;

  const RunResult by_sequence = runLvslam(dir, "eval --sequence seq --est out/trajectory.tum");
  ASSERT_EQ(by_sequence.exit_code, 0) << by_sequence.err;
  EXPECT_EQ(ateLine(by_sequence.out), expected) << by_sequence.out;
  EXPECT_TRUE(by_sequence.err.empty()) << by_sequence.err;

  const RunResult by_files = runLvslam(
      dir, "eval --gt seq/groundtruth.txt --gt-frame lidar --extrinsic seq/sequence.yaml --est out/trajectory.tum");
  ASSERT_EQ(by_files.exit_code, 0) << by_files.err;
  EXPECT_EQ(ateLine(by_files.out), expected) << by_files.out;

  // Without the frames the camera estimate meets the LiDAR truth as it is:
  // said in one warning line, and the lever arm shows in the figure.
  const RunResult blind = runLvslam(dir, "eval --gt seq/groundtruth.txt --est out/trajectory.tum");
  ASSERT_EQ(blind.exit_code, 0) << blind.err;
  EXPECT_EQ(lines(blind.err), 1) << blind.err;
  EXPECT_NE(blind.err.find("seq/groundtruth.txt: its sensor frame cannot be told"), std::string::npos) << blind.err;
  EXPECT_NE(ateLine(blind.out), expected) << blind.out;
}

TEST(EvalFrames, ExtrinsicFileWithATopLevelMatrix) {
  TempDir dir;
  lidarFrameGroundTruth(dir);
  ASSERT_EQ(runLvslam(dir, "run --sequence seq --mode lidar --out out").exit_code, 0);
  const SequenceInfo info = readSequenceInfo(dir.file("seq/sequence.yaml"));
  std::string matrix;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) matrix += (matrix.empty() ? "" : ", ") + std::to_string(info.T_camera_lidar(r, c));
  dir.write("ext.yaml", "T_camera_lidar: [" + matrix + "]\n");
  const std::string args = "eval --gt seq/groundtruth.txt --gt-frame lidar --est out/trajectory.tum";
  const RunResult with = runLvslam(dir, args + " --extrinsic ext.yaml");
  ASSERT_EQ(with.exit_code, 0) << with.err;
  EXPECT_EQ(ateLine(with.out), ateLine(runLvslam(dir, "eval --sequence seq --est out/trajectory.tum").out));
  const RunResult without = runLvslam(dir, args);
  EXPECT_EQ(without.exit_code, 2);
  EXPECT_EQ(lines(without.err), 1) << without.err;
  EXPECT_NE(without.err.find("--extrinsic: needed"), std::string::npos) << without.err;
}

TEST(EvalFrames, SequenceWithoutGroundTruthIsNamed) {
  TempDir dir;
  testing::cleanSequence(dir);
  std::filesystem::remove(dir.file("seq/groundtruth.txt"));
  dir.write("est.txt", "0 0 0 0 0 0 0 1\n");
  const RunResult r = runLvslam(dir, "eval --sequence seq --est est.txt");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("seq/groundtruth.txt: file not found"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace lvslam
