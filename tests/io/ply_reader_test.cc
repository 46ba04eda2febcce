#include "lvslam/io/ply_reader.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace lvslam {
namespace {

using testing::TempDir;

TEST(PlyReader, ReadsBackWhatTheWriterWrote) {
  TempDir dir;
  writePointCloudPly(dir.file("map.ply"), {{{1.5f, -2.0f, 3.25f}, 4.0f}, {{0.0f, 1.0f, 2.0f}, 0.0f}});
  const std::vector<PlyPoint> points = readPointCloudPly(dir.file("map.ply"));
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0].p, Eigen::Vector3f(1.5f, -2.0f, 3.25f));
  EXPECT_EQ(points[0].intensity, 4.0f);
  EXPECT_EQ(points[1].p, Eigen::Vector3f(0.0f, 1.0f, 2.0f));

  PlySegment s;
  s.a = Eigen::Vector3d(1, 2, 3);
  s.b = Eigen::Vector3d(-1, 0.5, 2);
  s.r = 10;
  s.g = 200;
  s.b_colour = 0;
  writeLineSegmentsPly(dir.file("lines.ply"), {s, s});
  const std::vector<PlySegment> lines = readLineSegmentsPly(dir.file("lines.ply"));
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_TRUE(lines[1].a.isApprox(s.a));
  EXPECT_TRUE(lines[1].b.isApprox(s.b));
  EXPECT_EQ(lines[1].g, 200);
}

TEST(PlyReader, ATruncatedMapIsNamed) {
  TempDir dir;
  writePointCloudPly(dir.file("map.ply"), std::vector<PlyPoint>(10));
  std::filesystem::resize_file(dir.file("map.ply"), std::filesystem::file_size(dir.file("map.ply")) - 5);
  const std::string message = testing::errorMessageOf([&] { readPointCloudPly(dir.file("map.ply")); });
  EXPECT_NE(message.find("map.ply: truncated"), std::string::npos) << message;
}

TEST(PlyReader, OtherLayoutsAreRefused) {
  TempDir dir;
  dir.write("other.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n1\n");
  EXPECT_NE(testing::errorMessageOf([&] { readPointCloudPly(dir.file("other.ply")); }).find("other.ply"),
            std::string::npos);
  dir.write("cut.ply", "ply\nformat ascii 1.0\nelement vertex 2\n");
  EXPECT_NE(testing::errorMessageOf([&] { readLineSegmentsPly(dir.file("cut.ply")); }).find("end_header"),
            std::string::npos);
}

}  // namespace
}  // namespace lvslam
