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

// Found by fuzz_ply: a count no file of this size can hold is refused
// before anything that large is allocated.
TEST(PlyReader, ACountTheFileCannotHoldIsRefused) {
  TempDir dir;
  dir.write("lines.ply",
            "ply\nformat ascii 1.0\nelement vertex 8888888888884\nproperty float x\nproperty float y\n"
            "property float z\nelement edge 1\nproperty int vertex1\nproperty int vertex2\nproperty uchar red\n"
            "property uchar green\nproperty uchar blue\nend_header\n0 0 0\n0 0 0 0 0\n");
  const std::string message = testing::errorMessageOf([&] { readLineSegmentsPly(dir.file("lines.ply")); });
  EXPECT_NE(message.find("lines.ply: truncated: the header announces 8888888888884 vertex elements"), std::string::npos)
      << message;
  dir.write("map.ply",
            "ply\nformat binary_little_endian 1.0\nelement vertex 4611686018427387904\nproperty float x\n"
            "property float y\nproperty float z\nproperty float intensity\nend_header\n");
  EXPECT_NE(testing::errorMessageOf([&] { readPointCloudPly(dir.file("map.ply")); }).find("map.ply: truncated"),
            std::string::npos);
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
