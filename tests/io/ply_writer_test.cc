#include "lvslam/io/ply_writer.h"

#include <cstring>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace lvslam {
namespace {

using testing::TempDir;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(PlyWriter, PointCloudIsBinaryWithExactValues) {
  TempDir dir;
  writePointCloudPly(dir.file("map.ply"), {{{1.5f, -2.0f, 3.25f}, 7.0f}, {{0.0f, 1.0f, 2.0f}, 0.5f}});
  const std::string data = slurp(dir.file("map.ply"));
  const std::string end = "end_header\n";
  const auto body = data.find(end);
  ASSERT_NE(body, std::string::npos);
  EXPECT_NE(data.find("element vertex 2\n"), std::string::npos);
  ASSERT_EQ(data.size() - body - end.size(), 2u * 4u * sizeof(float));
  float values[8];
  std::memcpy(values, data.data() + body + end.size(), sizeof(values));
  EXPECT_EQ(values[0], 1.5f);
  EXPECT_EQ(values[2], 3.25f);
  EXPECT_EQ(values[3], 7.0f);
  EXPECT_EQ(values[7], 0.5f);
}

TEST(PlyWriter, LinesAreVertexPairsJoinedByEdges) {
  TempDir dir;
  writeLineSegmentsPly(dir.file("lines.ply"), {{{0, 0, 0}, {1, 2, 3}}, {{4, 5, 6}, {7, 8, 9}}});
  const std::string text = slurp(dir.file("lines.ply"));
  EXPECT_NE(text.find("element vertex 4\n"), std::string::npos);
  EXPECT_NE(text.find("element edge 2\n"), std::string::npos);
  EXPECT_NE(text.find("7.000000 8.000000 9.000000\n"), std::string::npos);
  EXPECT_NE(text.find("\n2 3 255 0 255\n"), std::string::npos);
}

TEST(PlyWriter, UnwritablePathIsAnError) {
  EXPECT_THROW(writePointCloudPly("/nonexistent-dir/map.ply", {}), std::exception);
}

}  // namespace
}  // namespace lvslam
