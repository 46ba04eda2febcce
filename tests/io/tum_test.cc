#include "lvslam/io/tum.h"

#include <gtest/gtest.h>

#include "lvslam/core/se3.h"
#include "support/temp_dir.h"

namespace lvslam {
namespace {

using testing::errorMessageOf;
using testing::TempDir;

// Each pose is on disk once added (a killed run leaves them), in writeTum's format.
TEST(Tum, AStreamHasEachPoseOnDiskAsItIsAdded) {
  TempDir dir;
  Trajectory traj;
  for (int i = 0; i < 3; ++i) {
    Vector6d xi;
    xi << 0.5 * i, 0.1, -0.2 * i, 0.01, 0.02 * i, -0.3;
    traj.push_back({1628249320.5 + 0.1 * i, expSE3(xi)});
  }
  writeTum(dir.file("whole.tum"), traj);
  const std::string whole = testing::slurpBinary(dir.file("whole.tum"));
  TumStream stream(dir.file("stream.tum"));
  std::size_t written = 0;
  for (const StampedPose& pose : traj) {
    stream.add(pose);
    written = whole.find('\n', written) + 1;
    EXPECT_EQ(testing::slurpBinary(dir.file("stream.tum")), whole.substr(0, written));
  }
}

TEST(Tum, AStreamThatCannotBeWrittenIsNamed) {
  TempDir dir;
  EXPECT_NE(errorMessageOf([&] { TumStream(dir.file("no/such/folder/t.tum")); }).find("no/such/folder/t.tum: cannot write"),
            std::string::npos);
}

TEST(Tum, WriteReadRoundTrip) {
  TempDir dir;
  Trajectory traj;
  for (int i = 0; i < 50; ++i) {
    Vector6d xi;
    xi << 0.1 * i, -0.05 * i, 0.01 * i, 0.02 * i, -0.03 * i, 0.07 * i;
    traj.push_back({1628249320.123456 + 0.0667 * i, expSE3(xi)});
  }
  writeTum(dir.file("t.txt"), traj);
  const Trajectory back = readTum(dir.file("t.txt"));
  ASSERT_EQ(back.size(), traj.size());
  for (std::size_t i = 0; i < traj.size(); ++i) {
    EXPECT_NEAR(back[i].t, traj[i].t, 1e-6);
    EXPECT_LT((back[i].T_world_frame.translation() - traj[i].T_world_frame.translation()).norm(), 1e-8);
    EXPECT_LT(rotationAngle(back[i].T_world_frame.inverse() * traj[i].T_world_frame), 1e-8);
  }
}

TEST(Tum, CommentsAndBlankLinesAreSkipped) {
  TempDir dir;
  dir.write("t.txt", "# header\n\n1.0 1 2 3 0 0 0 1\n  # indented comment\n2.0 4 5 6 0 0 0.7071067811865476 0.7071067811865476\n");
  const Trajectory t = readTum(dir.file("t.txt"));
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[1].T_world_frame.translation(), Eigen::Vector3d(4, 5, 6));
  EXPECT_NEAR(rotationAngle(t[1].T_world_frame), M_PI / 2, 1e-12);
}

TEST(Tum, BadLineNamesFileAndLine) {
  TempDir dir;
  dir.write("t.txt", "1.0 1 2 3 0 0 0 1\n2.0 1 2 3 0 0 1\n");
  std::string msg = errorMessageOf([&] { readTum(dir.file("t.txt")); });
  EXPECT_NE(msg.find("t.txt:2"), std::string::npos) << msg;
  dir.write("t.txt", "1.0 1 2 3 0 0 0 1\n2.0 1 2 nan 0 0 0 1\n");
  msg = errorMessageOf([&] { readTum(dir.file("t.txt")); });
  EXPECT_NE(msg.find("t.txt:2"), std::string::npos) << msg;
  dir.write("t.txt", "1.0 1 2 3 0 0 0 0\n");
  msg = errorMessageOf([&] { readTum(dir.file("t.txt")); });
  EXPECT_NE(msg.find("zero norm"), std::string::npos) << msg;
}

TEST(Tum, UnsortedOrDuplicateStampsAreErrors) {
  TempDir dir;
  dir.write("t.txt", "2.0 1 2 3 0 0 0 1\n1.0 1 2 3 0 0 0 1\n");
  EXPECT_NE(errorMessageOf([&] { readTum(dir.file("t.txt")); }).find("t.txt:2"), std::string::npos);
  dir.write("t.txt", "1.0 1 2 3 0 0 0 1\n1.0 1 2 3 0 0 0 1\n");
  EXPECT_NE(errorMessageOf([&] { readTum(dir.file("t.txt")); }).find("t.txt:2"), std::string::npos);
}

TEST(Tum, MissingFileNamesIt) {
  EXPECT_NE(errorMessageOf([] { readTum("/no/such/traj.txt"); }).find("/no/such/traj.txt"), std::string::npos);
}

TEST(KittiPoses, ReadsRowMajorPosesWithTimes) {
  TempDir dir;
  dir.write("p.txt", "1 0 0 1 0 1 0 2 0 0 1 3\n0 -1 0 4 1 0 0 5 0 0 1 6\n");
  dir.write("t.txt", "0.0\n0.1\n");
  const Trajectory t = readKittiPoses(dir.file("p.txt"), dir.file("t.txt"));
  ASSERT_EQ(t.size(), 2u);
  EXPECT_DOUBLE_EQ(t[1].t, 0.1);
  EXPECT_EQ(t[1].T_world_frame.translation(), Eigen::Vector3d(4, 5, 6));
  EXPECT_NEAR(rotationAngle(t[1].T_world_frame), M_PI / 2, 1e-12);
  dir.write("t.txt", "0.0\n");
  EXPECT_NE(errorMessageOf([&] { readKittiPoses(dir.file("p.txt"), dir.file("t.txt")); }).find("t.txt"),
            std::string::npos);
  dir.write("t.txt", "# no stamps\n");  // an empty times file is not "no times file"
  EXPECT_NE(errorMessageOf([&] { readKittiPoses(dir.file("p.txt"), dir.file("t.txt")); }).find("0"),
            std::string::npos);
  dir.write("t.txt", "0.2\n0.1\n");
  EXPECT_NE(errorMessageOf([&] { readKittiPoses(dir.file("p.txt"), dir.file("t.txt")); }).find("t.txt:2"),
            std::string::npos);
}

}  // namespace
}  // namespace lvslam
